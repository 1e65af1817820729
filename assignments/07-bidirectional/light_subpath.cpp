// Lesson 7 — the light subpath y_0 .. y_{s-1} (Eq. 7.1, 7.3). Interface:
// lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void lightSubpath(const Scene& scene, Rng& rng, int maxDepth, Heuristic h, Subpath& path) {
    // TODO(07) The light subpath (Eq. 7.1, 7.3), like lesson 5's traceLightPath without the
    //          camera connections:
    //          1. path.clear(); start = startLightPath(scene, rng.uniform(), rng.uniform2(),
    //             rng.uniform2()); stop if not valid.
    //          2. y_0: kind Light, sp = start.y0, light = start.light, deltaPosition = the light
    //             is a point light, infinite = it is the background (then sp.n = the direction
    //             of start.ray), pdfFwd = pdfLightOrigin(scene, y_0), beta = 1 / pdfFwd.
    //          3. beta = start.beta, throughput = 1, ray = start.ray; for bounces = 1 .. maxDepth:
    //             a. scene.intersect(ray, sp), stop on a miss. Append y_i: kind Surface, sp,
    //                beta, delta = material.isDelta(); pdfFwd = pdfLightToward(y_0, y_1) for
    //                i = 1, else pdfScatter(scene, &y_{i-2}, y_{i-1}, y_i, Transport::Importance):
    //                the density of the direction sampled at y_{i-1}, evaluated from the vertices'
    //                positions with the same function the MIS weights use (after a delta vertex:
    //                its lobe's coefficient, Eq. 7.7a).
    //             b. If i >= 2: y_{i-2}.pdfRev = pdfScatter(scene, &y_i, y_{i-1}, y_{i-2},
    //                Transport::Radiance) (the camera's way). Then updateMisSum(path, i, h).
    //             c. Stop if bounces == maxDepth. sampleAdjointBSDF(m, sp.n, -ray.d,
    //                rng.uniform2(), rng.uniform(), s); stop if false; beta and throughput *= s.weight, stop if
    //                black; Russian roulette with survivalProbability(throughput, bounces)
    //                as in lesson 5; ray = scene.spawnRay(sp, s.wi).
    //          Call updateMisSum(path, i, h) for i = 0 and 1 as well (they are 0).
    //          Careful: take references into `path` only after push_back (it may reallocate).
    (void)scene; (void)rng; (void)maxDepth; (void)h;
    path.clear();
    (void)PS_TODO("lesson 07: lightSubpath", 0);
}

}  // namespace ps
