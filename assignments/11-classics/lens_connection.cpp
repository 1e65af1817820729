// Lesson 11 — bidirectional path tracing's technique t = 0: a light subpath that hits the lens.
// Interface: lessons/11-classics/thinlens.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/thinlens.h"
#include "todo.h"

namespace ps {

LensConnection connectLens(const Scene& scene, const PathVertex* y, int m, Rng& rng) {
    // TODO(11) Eq. 11.16, 11.17: one more step of the light walk from y_m, and the lens point it meets.
    //          1. The ray and beta': m = 0: start = startLightPath(scene, uLight, uPos, uDir)
    //             (rng.uniform(), rng.uniform2(), rng.uniform2(), drawn into variables in that
    //             order; invalid if not valid); the ray is start.ray,
    //             beta' = start.beta, and c.light the new y_0: its sp is start.y0, onLight,
    //             pointLight and infinite from its light, an infinite one's sp.n = -start.ray.d.
    //             m >= 1: sampleAdjointBSDF(y_m's material, y_m.sp.n, direction(y_m, y_{m-1}),
    //             u, uLobe, b) (rng.uniform2(), then rng.uniform(); invalid if it fails); the ray is
    //             scene.spawnRay(y_m.sp, b.wi), beta' = y_m.beta * b.weight.
    //          2. camera.hit(ray, t, z): invalid if it misses; then scene.occluded on the ray
    //             cut at t (ray.tMax = t): invalid if blocked.
    //          3. W = width * height * camera.We(z, -ray.d); invalid if 0. value = beta' W,
    //             raster = camera.rasterOfDirection(z, -ray.d), lens = cameraVertex(scene, z).
    //          Pitfalls: the numbers drawn in this order; a specular y_m is fine (t = 0 needs no
    //          connection at it); no cosine or 1 / d^2 in value: the step's density cancels them.
    (void)scene; (void)y; (void)m; (void)rng;
    return PS_TODO("lesson 11: connectLens", LensConnection());
}

}  // namespace ps
