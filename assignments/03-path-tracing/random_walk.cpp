// Lesson 3 — the random walk as an estimator: a path tracer that only samples BSDFs. Interface:
// lessons/03-path-tracing/pathtracer.h. Equation numbers refer to lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

Color LiRandomWalk(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    Color L(0.0f);
    cameraWalk(scene, cameraRay, rng, {maxDepth}, [&](const WalkVertex& v) {
        // TODO(03) What vertex x_k adds to L (Eq. 3.4): beta_k times the emission leaving it
        //          towards the previous vertex, the background's radiance where the walk left
        //          the scene; then return true (the walk decides where it ends).
        //          Pitfall: emittedRadiance wants the direction the light leaves in: v.wo.
        (void)v;
        return PS_TODO("lesson 03: LiRandomWalk", false);
    });
    return L;
}

}  // namespace ps
