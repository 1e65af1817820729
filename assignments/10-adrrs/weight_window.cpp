// Lesson 10 — the weight window and the expected number of continuations it gives. Interface:
// lessons/10-adrrs/adrrs.h. Equation numbers refer to lessons/10-adrrs/README.md.
#include <algorithm>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

WeightWindow weightWindow(float pixelEstimate, float adjoint, float ratio) {
    // TODO(10) Eq. 10.5, 10.6: the centre C_ww = I~ / Psi~ (pixelEstimate / adjoint), the lower
    //          bound delta- = 2 C_ww / (1 + s) and the upper bound delta+ = s delta- (s = ratio),
    //          so that C_ww is their midpoint. adjoint <= 0: all three +infinity (kInf).
    (void)pixelEstimate; (void)adjoint; (void)ratio;
    return PS_TODO("lesson 10: weightWindow", WeightWindow());
}

float expectedContinuations(float weight, const WeightWindow& window) {
    // TODO(10) Eq. 10.7: below the window (weight < lower) q = weight / lower (roulette: the
    //          survivors come out at the lower bound), above it (weight > upper) q = weight /
    //          upper (splitting: each continuation at the upper bound), inside it (bounds
    //          included) q = 1; then clamp q to [kMinContinuations, kMaxContinuations].
    //          Pitfall: the bounds may be +infinity (weight / inf = 0: the clamp makes it
    //          kMinContinuations) or 0 (weight / 0 = inf: the clamp makes it kMaxContinuations).
    (void)weight; (void)window;
    return PS_TODO("lesson 10: expectedContinuations", 1.0f);
}

}  // namespace ps
