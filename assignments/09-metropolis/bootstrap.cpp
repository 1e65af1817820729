// Lesson 9 — the bootstrap of PSSMLT: b and where the chains start. Interface:
// lessons/09-metropolis/pssmlt.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

Bootstrap bootstrapChains(const std::vector<float>& I, int chains, Rng& rng) {
    // TODO(09) b and the chains' stratified starts of Eq. 9.10, as bootstrapChains in pssmlt.h states them (one number
    //          per chain, in chain order). Pitfall: a point past the CDF's end by rounding starts at the last seed
    //          with I > 0.
    (void)I; (void)chains; (void)rng;
    return PS_TODO("lesson 09: bootstrapChains", Bootstrap{});
}

}  // namespace ps
