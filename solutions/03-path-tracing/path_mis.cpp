// Lesson 3 — path tracing with next-event estimation and BSDF hits combined by MIS.
// Interface: lessons/03-path-tracing/pathtracer.h. Equation numbers refer to
// lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color LiMIS(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    //! TODO(03) LiNextEvent with both techniques weighted by kPathHeuristic (Eq. 3.7). Remember
    //!          from the last BSDF sample its pdf (pdfPrev), whether it was delta (specular) and
    //!          the point it left (pPrev).
    //!          1. Emission found by the walk (background where it leaves, or the hit surface's
    //!             emission): weight 1 if specular, else
    //!             misWeight(kPathHeuristic, 1, pdfPrev, 1, pdfLight) with pdfLight =
    //!             pdfLightDirection(scene, light, pPrev, sp.p, sp.n) (light = sp.light, or
    //!             scene.background for the background).
    //!          2. Stop if bounces == maxDepth.
    //!          3. Unless the material is delta: d = sampleDirectLight(...); add
    //!             beta * d.value * misWeight(kPathHeuristic, 1, d.pdfLight, 1, d.pdfBSDF).
    //!          4. Sample the BSDF, remember pdfPrev = s.pdf, specular = s.delta, pPrev = sp.p;
    //!             update beta, Russian roulette, next ray: as in LiRandomWalk.
    //! STUB (void)scene; (void)cameraRay; (void)rng; (void)maxDepth;
    //! STUB return PS_TODO("lesson 03: LiMIS", Color(0.0f));
    //! BEGIN
    Color L(0.0f), beta(1.0f);
    Ray ray = cameraRay;
    bool specular = true;
    float pdfPrev = 0.0f;
    Vec3 pPrev(0.0f);
    for (int bounces = 0;; ++bounces) {
        SurfacePoint sp;
        const bool hit = scene.intersect(ray, sp);
        // Emission found by the walk: the background where it leaves, or the surface it hits.
        const int light = hit ? sp.light : scene.background;
        if (light >= 0) {
            const Color Le = hit ? emittedRadiance(scene.lights[light], sp.n, -ray.d) : scene.backgroundRadiance();
            if (!isBlack(Le)) {
                const float w = specular ? 1.0f
                                         : misWeight(kPathHeuristic, 1.0f, pdfPrev, 1.0f,
                                                     pdfLightDirection(scene, light, pPrev, sp.p, sp.n));
                L += beta * Le * w;
            }
        }
        if (!hit || bounces == maxDepth) break;
        const Vec3 wo = -ray.d;
        const Material& m = scene.materials[sp.material];
        if (!m.isDelta()) {
            const DirectSample d = sampleDirectLight(scene, sp, wo, rng.uniform(), rng.uniform2());
            L += beta * d.value * misWeight(kPathHeuristic, 1.0f, d.pdfLight, 1.0f, d.pdfBSDF);
        }
        BSDFSample s;
        if (!sampleBSDF(m, sp.n, wo, rng.uniform2(), rng.uniform(), Transport::Radiance, s)) break;
        specular = s.delta;
        pdfPrev = s.pdf;
        pPrev = sp.p;
        beta *= s.weight;
        if (isBlack(beta)) break;
        const float q = survivalProbability(beta, bounces + 1);
        if (q < 1.0f) {
            if (rng.uniform() >= q) break;
            beta /= q;
        }
        ray = scene.spawnRay(sp, s.wi);
    }
    return L;
    //! END
}

}  // namespace ps
