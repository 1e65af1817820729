// Lesson 10 — survival and splitting: the number of continuations and their weight. Interface:
// lessons/10-adrrs/adrrs.h. Equation numbers refer to lessons/10-adrrs/README.md.
#include <cmath>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

Continuations continuations(const Color& beta, float q, Rng& rng) {
    // TODO(10) Eq. 10.3, 10.4: n = floor(q), plus one if rng.uniform() < q - floor(q) (draw that
    //          number only when q - floor(q) > 0), so that E[n] = q; every continuation carries
    //          beta / q (also when q < 1: that is Russian roulette's survivor weight).
    //          Pitfall: floor(q) alone loses the fraction (E[n] < q: the image is too dark),
    //          and weighting by beta / n instead of beta / q is biased.
    (void)beta; (void)q; (void)rng;
    return PS_TODO("lesson 10: continuations", Continuations());
}

}  // namespace ps
