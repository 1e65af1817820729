// Lesson 4 — the flux through a region S, measured from the lights. Interface:
// lessons/04-measurement/measurement.h. Equation numbers refer to lessons/04-measurement/README.md.
#include "04-measurement/measurement.h"
#include "todo.h"

namespace ps {

Color fluxParticle(const Scene& scene, const Region& S, Rng& rng) {
    //! TODO(04) One particle's share of Phi_S (Eq. 4.12, 4.13), random numbers in measurement.h's order. Pitfalls: P(l)
    //!          left out; a cosine at a point light or the background (README 6; light.h).
    //! STUB (void)scene; (void)S; (void)rng;
    //! STUB return PS_TODO("lesson 04: fluxParticle", Color(0.0f));
    //! BEGIN
    float P = 0.0f;
    const int l = scene.selectLight(rng.uniform(), P);
    if (l < 0 || P <= 0.0f) return Color(0.0f);
    // Named, in this order: C++ evaluates a call's arguments in no fixed order.
    const Vec2 uPos = rng.uniform2();
    const Vec2 uDir = rng.uniform2();
    const EmissionSample e = sampleEmission(scene, l, uPos, uDir);
    if (!(e.pdfA > 0.0f && e.pdfW > 0.0f)) return Color(0.0f);
    const Light& light = scene.lights[l];
    const float cosTheta = light.kind == LightKind::Area ? std::abs(glm::dot(e.n, e.dir)) : 1.0f;
    const Color power = e.Le * (cosTheta / (P * e.pdfA * e.pdfW));
    Ray ray = scene.spawnRay(emissionPoint(scene, l, e), e.dir);
    SurfacePoint sp;
    if (!scene.intersect(ray, sp) || !S.contains(sp.prim)) return Color(0.0f);
    return power;
    //! END
}

}  // namespace ps
