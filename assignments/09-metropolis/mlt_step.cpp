// Lesson 9 — one Metropolis step of a PSSMLT chain, splatting with expected values. Interface:
// lessons/09-metropolis/pssmlt.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

float mltStep(Chain& chain, float pLarge, Rng& rng, const PathEvaluator& evaluate, const SplatFunction& splat) {
    // TODO(09) One PSSMLT step of Eq. 9.11 with the expected-values splats of Eq. 9.5, as mltStep in pssmlt.h states
    //          it, numbers drawn in that order; the proposal is evaluated through an Rng replaying chain.samples
    //          (framework/rng.h). Pitfall (README 6): each splat is divided by its own I.
    (void)chain; (void)pLarge; (void)rng; (void)evaluate; (void)splat;
    return PS_TODO("lesson 09: mltStep", 0.0f);
}

}  // namespace ps
