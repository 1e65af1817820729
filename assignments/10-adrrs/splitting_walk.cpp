// Lesson 10 — the walk with survival and splitting (Algorithm 10.1): lesson 3's random walk,
// which may go on from a vertex any number of times. Interface: lessons/10-adrrs/adrrs.h.
// Equation numbers refer to lessons/10-adrrs/README.md and lessons/03-path-tracing/README.md.
#include <algorithm>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

void splittingWalk(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth, const ContinuationRule& rule,
                   const WalkVisitor& visit) {
    // TODO(10) Algorithm 10.1: the tree of paths from cameraRay, depth first. A vertex is filled
    //          and visited as in lesson 3's cameraWalk (the escape too; beta_0 = 1, specular at
    //          bounces 0). From a vertex the walk may go on from (hit, visit returned true,
    //          bounces < maxDepth): q = rule(v), cut to min(q, 1) once kMaxPathsPerCameraRay
    //          paths have been started (1 + the extra continuations n - 1 of every split so far);
    //          c = continuations(v.beta, q, rng); then c.n times: sample the BSDF with
    //          sampleBSDF(material, n, wo, u, uLobe, Transport::Radiance, s), u = rng.uniform2()
    //          drawn before uLobe = rng.uniform() (this continuation ends if it fails or
    //          c.beta * s.weight is black) and follow the new path (scene.spawnRay) to its very
    //          end before the next continuation samples.
    //          Pitfall: recursion as deep as maxDepth may overflow the stack (the extreme tests
    //          use maxDepth 100000): keep the open vertices in a std::vector.
    (void)scene; (void)cameraRay; (void)rng; (void)maxDepth; (void)rule; (void)visit;
    (void)PS_TODO("lesson 10: splittingWalk", 0);
}

}  // namespace ps
