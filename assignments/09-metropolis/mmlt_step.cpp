// Lesson 9 — one step of a multiplexed MLT chain: a technique mutation, a large or a small step,
// accepted with the transition probabilities and splatted with expected values. Interface:
// lessons/09-metropolis/mmlt.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include <utility>
#include "09-metropolis/mmlt.h"
#include "todo.h"

namespace ps {

float mmltStep(MultiplexedChain& chain, const MMLTMutations& m, Rng& rng, const SubpathTracer& trace,
               const TechniqueTarget& target, const SplatFunction& splat) {
    // TODO(09) One MMLT step (Eq. 9.14), as mmltStep in mmlt.h states it, numbers drawn in that order. Pitfalls
    //          (README 6): the technique mutation's T are not symmetric next to the ends (Eq. 9.13); it traces nothing
    //          and touches no stream; an accepted large or small step keeps its subpaths.
    (void)chain; (void)m; (void)rng; (void)trace; (void)target; (void)splat;
    return PS_TODO("lesson 09: mmltStep", 0.0f);
}

}  // namespace ps
