// Lesson 10 — the walk with survival and splitting (Algorithm 10.1): lesson 3's camera walk with a
// continuation rule, which may go on from a vertex any number of times. Interface:
// lessons/10-adrrs/adrrs.h. Equation numbers refer to lessons/10-adrrs/README.md and
// lessons/03-path-tracing/README.md.
#include <algorithm>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

void splittingWalk(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth,
                   const ExpectedContinuations& expected, const WalkVisitor& visit) {
    // TODO(10) Algorithm 10.1 on lesson 3's cameraWalk with a continuation rule (Eq. 3.10), as splittingWalk in
    //          adrrs.h states it (the cap, kNoDecision). Pitfall (README 6): one roulette per vertex where the rule
    //          decides.
    (void)scene; (void)cameraRay; (void)rng; (void)maxDepth; (void)expected; (void)visit;
    (void)PS_TODO("lesson 10: splittingWalk", 0);
}

}  // namespace ps
