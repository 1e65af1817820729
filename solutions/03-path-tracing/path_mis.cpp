// Lesson 3 — path tracing with next-event estimation and BSDF hits combined by MIS.
// Interface: lessons/03-path-tracing/pathtracer.h. Equation numbers refer to
// lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color misEmission(const Scene& scene, const WalkVertex& v) {
    //! TODO(03) The first half of Eq. 3.7 at x_k: beta_k times the emission the walk finds (the hit
    //!          light sp.light, or scene.background where it left) with weight 1 after a specular
    //!          bounce, else the BSDF sample's weight from v.pdfPrev against the density with which a
    //!          light sample at the previous vertex would have chosen it (lesson 2's
    //!          pdfLightDirection); black if there is none.
    //!          Pitfall: both densities of the hit belong to x_{k-1} (v.pPrev), not to x_k.
    //! STUB (void)scene; (void)v;
    //! STUB return PS_TODO("lesson 03: misEmission (LiMIS)", Color(0.0f));
    //! BEGIN
    const int light = v.hit ? v.sp.light : scene.background;
    if (light < 0) return Color(0.0f);
    const Color Le = v.hit ? emittedRadiance(scene.lights[light], v.sp.n, v.wo) : scene.backgroundRadiance();
    if (isBlack(Le)) return Color(0.0f);
    const float w = v.specular ? 1.0f
                               : misWeight(kPathHeuristic, 1.0f, v.pdfPrev, 1.0f,
                                           pdfLightDirection(scene, light, v.pPrev, v.sp.p, v.sp.n));
    return v.beta * Le * w;
    //! END
}

Color misLightSample(const Scene& scene, const WalkVertex& v, Rng& rng, int maxDepth) {
    //! TODO(03) The second half of Eq. 3.7 at x_k, where LiNextEvent takes one: beta_k times the
    //!          light sample (its numbers drawn as in LiNextEvent), weighted by kPathHeuristic from
    //!          DirectSample's light density against the density with which the walk itself leaves
    //!          x_k in that direction (pdfWalk).
    //!          Pitfall: the light sample at the vertex with maxDepth bounces would make a path
    //!          of maxDepth + 1 bounces.
    //! STUB (void)scene; (void)v; (void)rng; (void)maxDepth;
    //! STUB return PS_TODO("lesson 03: misLightSample (LiMIS)", Color(0.0f));
    //! BEGIN
    if (!v.hit || v.bounces == maxDepth || scene.materials[v.sp.material].isDelta()) return Color(0.0f);
    // Named, in this order: C++ evaluates a call's arguments in no fixed order.
    const float uLight = rng.uniform();
    const Vec2 uPoint = rng.uniform2();
    const DirectSample d = sampleDirectLight(scene, v.sp, v.wo, uLight, uPoint);
    return v.beta * d.value * misWeight(kPathHeuristic, 1.0f, d.pdfLight, 1.0f, pdfWalk(scene, v, d));
    //! END
}

Color LiMIS(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    Color L(0.0f);
    cameraWalk(scene, cameraRay, rng, {maxDepth}, [&](const WalkVertex& v) {
        addMISContribution(scene, v, rng, maxDepth, L);
        return true;
    });
    return L;
}

}  // namespace ps
