// Lesson 3 — path tracing with next-event estimation. Interface:
// lessons/03-path-tracing/pathtracer.h. Equation numbers refer to lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color LiNextEvent(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    Color L(0.0f);
    cameraWalk(scene, cameraRay, rng, {maxDepth}, [&](const WalkVertex& v) {
        // TODO(03) What vertex x_k adds to L with next-event estimation (Eq. 3.6); return true. The light sample's
        //          numbers: uLight, then uPoint, each into a variable (README 2 says why the tests replay them).
        //          Pitfalls (README 6): light counted twice or never, a light sample that makes a path of maxDepth + 1
        //          bounces or sits on a delta material.
        (void)v;
        return PS_TODO("lesson 03: LiNextEvent", false);
    });
    return L;
}

}  // namespace ps
