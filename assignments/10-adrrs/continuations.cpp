// Lesson 10 — survival and splitting: the number of continuations and their weight. Interface:
// lessons/10-adrrs/adrrs.h. Equation numbers refer to lessons/10-adrrs/README.md.
#include <cmath>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

Continuations continuations(const Color& beta, float q, Rng& rng) {
    // TODO(10) n continuations with E[n] = q and their throughput (Eq. 10.3, 10.4), drawing as adrrs.h states (the
    //          tests replay it). Pitfalls (README 6): divide by q, not n; round at random both ways.
    (void)beta; (void)q; (void)rng;
    return PS_TODO("lesson 10: continuations", Continuations());
}

}  // namespace ps
