// Lesson 5 — the start of a light path: emission sampling. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

LightPathStart startLightPath(const Scene& scene, float uLight, const Vec2& uPos, const Vec2& uDir) {
    //! TODO(05) The first vertex y0, its density P(l) p_A and the particle's power beta_1 leaving it (Eq. 5.2), started
    //!          as lesson 4's particles (Eq. 4.13). Pitfall: a cosine at a point light or the background.
    //! STUB (void)scene; (void)uLight; (void)uPos; (void)uDir;
    //! STUB return PS_TODO("lesson 05: startLightPath", LightPathStart());
    //! BEGIN
    LightPathStart s;
    float P = 0.0f;
    const int l = scene.selectLight(uLight, P);
    if (l < 0 || P <= 0.0f) return s;
    const EmissionSample e = sampleEmission(scene, l, uPos, uDir);
    if (!(e.pdfA > 0.0f && e.pdfW > 0.0f)) return s;
    const float cosTheta = scene.lights[l].kind == LightKind::Area ? std::abs(glm::dot(e.n, e.dir)) : 1.0f;
    s.light = l;
    s.y0 = emissionPoint(scene, l, e);
    s.pdfA = P * e.pdfA;
    s.ray = scene.spawnRay(s.y0, e.dir);
    s.beta = e.Le * (cosTheta / (s.pdfA * e.pdfW));
    s.valid = true;
    return s;
    //! END
}

}  // namespace ps
