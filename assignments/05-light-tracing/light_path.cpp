// Lesson 5 — one light path, connected to the camera at every vertex. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

void traceLightPath(const Scene& scene, Rng& rng, int maxDepth, const SplatTarget& out) {
    // TODO(05) The light path (Eq. 5.1-5.4):
    //          1. start = startLightPath(scene, rng.uniform(), rng.uniform2(), rng.uniform2());
    //             stop if it is not valid.
    //          2. 0 bounces, the light seen directly: unless the light is the background,
    //             c = connectToCamera(scene, start.y0, onSurface = the light is not a point
    //             light); if valid, add Le / start.pdfA * c.importance at c.raster, where Le is
    //             the light's intensity (point light) or emittedRadiance(light, y0.n, c.wCam).
    //          3. beta = start.beta, ray = start.ray, throughput = 1 (the product of the
    //             weights since the light, for Russian roulette); for bounces = 1, 2, ...,
    //             maxDepth:
    //             a. scene.intersect(ray, sp), stop on a miss; wLight = -ray.d.
    //             b. Unless the material is delta: c = connectToCamera(scene, sp, true); if
    //                valid, add beta * evalBSDF(m, sp.n, c.wCam, wLight) * c.importance.
    //             c. Stop if bounces == maxDepth.
    //             d. sampleAdjointBSDF(m, sp.n, wLight, rng.uniform2(), rng.uniform(), s),
    //                stop if false; beta and throughput *= s.weight; stop if beta is black.
    //             e. Russian roulette: q = survivalProbability(throughput, bounces); if q < 1,
    //                stop if rng.uniform() >= q, else divide beta and throughput by q.
    //             f. ray = scene.spawnRay(sp, s.wi).
    (void)scene; (void)rng; (void)maxDepth; (void)out;
    (void)PS_TODO("lesson 05: traceLightPath", 0);
}

}  // namespace ps
