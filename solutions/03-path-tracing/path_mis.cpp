// Lesson 3 — path tracing with next-event estimation and BSDF hits combined by MIS.
// Interface: lessons/03-path-tracing/pathtracer.h. Equation numbers refer to
// lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

void addMISContribution(const Scene& scene, const WalkVertex& v, Rng& rng, int maxDepth, Color& L) {
    //! TODO(03) Add to L what vertex x_k adds with both techniques weighted by kPathHeuristic
    //!          (Eq. 3.7): the emission the walk finds (the hit light sp.light, or
    //!          scene.background where it left) with weight 1 after a specular bounce, else
    //!          the BSDF sample's weight from v.pdfPrev against the density with which a
    //!          light sample at the previous vertex would have chosen it (lesson 2's
    //!          pdfLightDirection); then, where LiNextEvent takes one, the light sample with
    //!          its weight from DirectSample's two densities (two additions to L, in that order).
    //!          Pitfall: both densities of the hit belong to x_{k-1} (v.pPrev), not to x_k.
    //! STUB (void)scene; (void)v; (void)rng; (void)maxDepth; (void)L;
    //! STUB (void)PS_TODO("lesson 03: addMISContribution (LiMIS)", 0);
    //! BEGIN
    // Emission found by the walk: the background where it leaves, or the surface it hits.
    const int light = v.hit ? v.sp.light : scene.background;
    if (light >= 0) {
        const Color Le = v.hit ? emittedRadiance(scene.lights[light], v.sp.n, v.wo) : scene.backgroundRadiance();
        if (!isBlack(Le)) {
            const float w = v.specular ? 1.0f
                                       : misWeight(kPathHeuristic, 1.0f, v.pdfPrev, 1.0f,
                                                   pdfLightDirection(scene, light, v.pPrev, v.sp.p, v.sp.n));
            L += v.beta * Le * w;
        }
    }
    if (!v.hit || v.bounces == maxDepth || scene.materials[v.sp.material].isDelta()) return;
    // Named, in this order: C++ evaluates a call's arguments in no fixed order.
    const float uLight = rng.uniform();
    const Vec2 uPoint = rng.uniform2();
    const DirectSample d = sampleDirectLight(scene, v.sp, v.wo, uLight, uPoint);
    L += v.beta * d.value * misWeight(kPathHeuristic, 1.0f, d.pdfLight, 1.0f, d.pdfBSDF);
    //! END
}

Color LiMIS(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    Color L(0.0f);
    cameraWalk(scene, cameraRay, rng, maxDepth, [&](const WalkVertex& v) {
        addMISContribution(scene, v, rng, maxDepth, L);
        return true;
    });
    return L;
}

}  // namespace ps
