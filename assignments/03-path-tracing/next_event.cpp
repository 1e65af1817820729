// Lesson 3 — path tracing with next-event estimation. Interface:
// lessons/03-path-tracing/pathtracer.h. Equation numbers refer to lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color LiNextEvent(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    // TODO(03) The random walk of LiRandomWalk with next-event estimation (Eq. 3.6). Keep a flag
    //          `specular` (true before the first bounce and after a delta BSDF sample, s.delta):
    //          1. No hit: add beta * background only if specular; stop.
    //          2. Emission of the hit surface: add it only if specular (otherwise the light
    //             sample of the previous vertex has already counted this path).
    //          3. Stop if bounces == maxDepth.
    //          4. Unless the material is delta (Material::isDelta), add
    //             beta * sampleDirectLight(scene, sp, -ray.d, rng.uniform(), rng.uniform2()).value
    //             (lesson 2; that path has bounces + 1 bounces).
    //          5. Sample the BSDF, update beta and `specular`, Russian roulette, next ray: as in
    //             LiRandomWalk.
    (void)scene; (void)cameraRay; (void)rng; (void)maxDepth;
    return PS_TODO("lesson 03: LiNextEvent", Color(0.0f));
}

}  // namespace ps
