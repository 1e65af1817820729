// Lesson 4 — the flux through a region S, measured from the lights. Interface:
// lessons/04-measurement/measurement.h. Equation numbers refer to lessons/04-measurement/README.md.
#include "04-measurement/measurement.h"
#include "todo.h"

namespace ps {

Color fluxParticle(const Scene& scene, const Region& S, Rng& rng) {
    //! TODO(04) One particle (Eq. 4.12, 4.13), drawing the random numbers in this order:
    //!          1. l = scene.selectLight(rng.uniform(), P); return 0 if l < 0.
    //!          2. e = sampleEmission(scene, l, uPos, uDir), uPos = rng.uniform2() drawn before
    //!             uDir = rng.uniform2() (into variables: a call's arguments have no order);
    //!             return 0 if e.pdfA or e.pdfW is 0.
    //!          3. The particle's power: Le |cos theta| / (P pdfA pdfW), cos theta between e.n
    //!             and e.dir for an area light; a point light (Light::isDelta) and the
    //!             background have no cosine here (their Le is an intensity, or the disk they
    //!             start on faces e.dir).
    //!          4. Trace scene.spawnRay(emissionPoint(scene, l, e), e.dir); return the power if
    //!             it hits a primitive of S (S.contains(sp.prim)), else 0.
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
