// Lesson 10 — the weight window and the expected number of continuations it gives. Interface:
// lessons/10-adrrs/adrrs.h. Equation numbers refer to lessons/10-adrrs/README.md.
#include <algorithm>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

WeightWindow weightWindow(float pixelEstimate, float adjoint, float ratio) {
    // TODO(10) The weight window of Eq. 10.5, 10.6 (adrrs.h). Pitfall (README 6): the centre is a weight, I~ / Psi~.
    (void)pixelEstimate; (void)adjoint; (void)ratio;
    return PS_TODO("lesson 10: weightWindow", WeightWindow());
}

float expectedContinuations(float weight, const WeightWindow& window) {
    // TODO(10) q of Eq. 10.7 (adrrs.h). Pitfall: a bound of +infinity or 0 must still give a q within the clamp.
    (void)weight; (void)window;
    return PS_TODO("lesson 10: expectedContinuations", 1.0f);
}

}  // namespace ps
