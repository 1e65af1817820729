// Lesson 3 — path tracing with next-event estimation and BSDF hits combined by MIS.
// Interface: lessons/03-path-tracing/pathtracer.h. Equation numbers refer to
// lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color misEmission(const Scene& scene, const WalkVertex& v) {
    //! TODO(03) The first half of Eq. 3.7 at x_k: beta_k times the emission found there, weighted against light
    //!          sampling at x_{k-1} (weight 1 after a specular bounce); black if none. Pitfall: both densities belong
    //!          to x_{k-1} (README 6).
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
    //! TODO(03) The second half of Eq. 3.7 at x_k: beta_k times one light sample drawn as in LiNextEvent, weighted by
    //!          kPathHeuristic against the density with which the walk leaves x_k that way (pdfWalk, walk.h). Pitfall:
    //!          a light sample at the vertex with maxDepth bounces (README 6, off by one).
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
