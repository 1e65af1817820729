// Lesson 3 — the random walk: a path tracer that only samples BSDFs. Interface:
// lessons/03-path-tracing/pathtracer.h. Equation numbers refer to lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color LiRandomWalk(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    // TODO(03) The random walk (Eq. 3.3, 3.4). L = 0, throughput beta = 1, ray = cameraRay;
    //          for bounces = 0, 1, 2, ...:
    //          1. scene.intersect(ray, sp); no hit: add beta * scene.backgroundRadiance(), stop.
    //          2. sp.light >= 0: add beta * emittedRadiance(scene.lights[sp.light], sp.n, -ray.d)
    //             (that path has `bounces` bounces).
    //          3. Stop if bounces == maxDepth (Eq. 3.3).
    //          4. sampleBSDF(scene.materials[sp.material], sp.n, -ray.d, rng.uniform2(),
    //             rng.uniform(), Transport::Radiance, s); stop if it fails. beta *= s.weight
    //             (f |cos| / pdf); stop if beta is black.
    //          5. Russian roulette (Eq. 3.5): q = survivalProbability(beta, bounces + 1); stop
    //             if rng.uniform() >= q, else beta /= q. (Draw the number only when q < 1.)
    //          6. ray = scene.spawnRay(sp, s.wi).
    (void)scene; (void)cameraRay; (void)rng; (void)maxDepth;
    return PS_TODO("lesson 03: LiRandomWalk", Color(0.0f));
}

}  // namespace ps
