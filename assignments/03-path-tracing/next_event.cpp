// Lesson 3 — path tracing with next-event estimation. Interface:
// lessons/03-path-tracing/pathtracer.h. Equation numbers refer to lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color LiNextEvent(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    Color L(0.0f);
    cameraWalk(scene, cameraRay, rng, {maxDepth}, [&](const WalkVertex& v) {
        // TODO(03) What vertex x_k adds to L with next-event estimation (Eq. 3.6): the emission
        //          the walk finds (surface or background) only where no light sample could
        //          have found it (v.specular); then, if k < maxDepth and the material is not
        //          delta, beta_k times one light sample, lesson 2's sampleDirectLight(scene,
        //          v.sp, v.wo, uLight, uPoint).value, uLight = rng.uniform() drawn before
        //          uPoint = rng.uniform2() (into variables: a call's arguments have no order).
        //          Return true.
        //          Pitfall: the light sample at x_k makes a path of k + 1 bounces.
        (void)v;
        return PS_TODO("lesson 03: LiNextEvent", false);
    });
    return L;
}

}  // namespace ps
