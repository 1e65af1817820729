// Lesson 7 — the camera subpath z_0 .. z_{t-1} (Eq. 7.1, 7.3). Interface:
// lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void cameraSubpath(const Scene& scene, Rng& rng, const Vec2& raster, int maxDepth, Heuristic h, Subpath& path) {
    // TODO(07) The camera subpath (Eq. 7.1, 7.3), a random walk like lesson 3's:
    //          1. path.clear(); z_0: kind Camera, sp.p = camera.position(), sp.n =
    //             camera.forward(), deltaPosition = true, beta = 1, pdfFwd = 1 (the pinhole is
    //             chosen with probability 1: a delta position); updateMisSum(path, 0, h).
    //             ray = camera.generateRay(raster), beta = 1 (the pixel's estimate is the
    //             radiance itself), throughput = 1.
    //          2. For i = 1 .. maxDepth + 1:
    //             a. On a miss: if the scene has a background (scene.background >= 0) append
    //                z_i: kind Light, infinite, light = scene.background, sp.n = -ray.d, beta,
    //                pdfFwd as in b. (per solid angle: convertToArea leaves it); then stop.
    //             b. On a hit sp: z_i: kind Surface, sp, beta, light = sp.light, delta =
    //                material.isDelta(), pdfFwd = pdfScatter(scene, &z_{i-2} (null for i = 1),
    //                z_{i-1}, z_i, Transport::Radiance) (the camera walks against the light): evaluated from the positions with the function the MIS
    //                weights use, not the sample's s.pdf (the ray starts off the surface, so the
    //                two differ slightly, and the weights would no longer sum to 1).
    //             For both: after appending, if i >= 2 set z_{i-2}.pdfRev = pdfScatter(scene,
    //             &z_i, z_{i-1}, z_{i-2}, Transport::Importance) (the light's way); updateMisSum(path, i, h).
    //             c. Stop if i == maxDepth + 1. sampleBSDF(m, sp.n, -ray.d, rng.uniform2(),
    //                rng.uniform(), Transport::Radiance, s), stop if false; beta and throughput *= s.weight, stop if black;
    //                Russian roulette with survivalProbability(throughput, i);
    //                ray = scene.spawnRay(sp, s.wi).
    (void)scene; (void)rng; (void)raster; (void)maxDepth; (void)h;
    path.clear();
    (void)PS_TODO("lesson 07: cameraSubpath", 0);
}

}  // namespace ps
