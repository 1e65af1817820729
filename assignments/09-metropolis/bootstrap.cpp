// Lesson 9 — the bootstrap of PSSMLT: b and where the chains start. Interface:
// lessons/09-metropolis/pssmlt.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

Bootstrap bootstrapChains(const std::vector<float>& I, int chains, Rng& rng) {
    // TODO(09) Eq. 9.10: b = the mean of I (in double). If the sum is 0, return b = 0 and no
    //          starts. Else chain c = 0 .. chains - 1 starts at the lowest index i whose running
    //          sum I[0] + ... + I[i] exceeds (c + rng.uniform()) / chains times the total (one
    //          number per chain, in order; past the end: the last i with I[i] > 0).
    (void)I; (void)chains; (void)rng;
    return PS_TODO("lesson 09: bootstrapChains", Bootstrap{});
}

}  // namespace ps
