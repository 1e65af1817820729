// Lesson 3 — path tracing with next-event estimation and BSDF hits combined by MIS.
// Interface: lessons/03-path-tracing/pathtracer.h. Equation numbers refer to
// lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color LiMIS(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    // TODO(03) LiNextEvent with both techniques weighted by kPathHeuristic (Eq. 3.7). Remember
    //          from the last BSDF sample its pdf (pdfPrev), whether it was delta (specular) and
    //          the point it left (pPrev).
    //          1. Emission found by the walk (background where it leaves, or the hit surface's
    //             emission): weight 1 if specular, else
    //             misWeight(kPathHeuristic, 1, pdfPrev, 1, pdfLight) with pdfLight =
    //             pdfLightDirection(scene, light, pPrev, sp.p, sp.n) (light = sp.light, or
    //             scene.background for the background).
    //          2. Stop if bounces == maxDepth.
    //          3. Unless the material is delta: d = sampleDirectLight(...); add
    //             beta * d.value * misWeight(kPathHeuristic, 1, d.pdfLight, 1, d.pdfBSDF).
    //          4. Sample the BSDF, remember pdfPrev = s.pdf, specular = s.delta, pPrev = sp.p;
    //             update beta, Russian roulette, next ray: as in LiRandomWalk.
    (void)scene; (void)cameraRay; (void)rng; (void)maxDepth;
    return PS_TODO("lesson 03: LiMIS", Color(0.0f));
}

}  // namespace ps
