// Lesson 12 — roulette and splitting from an adjoint: lesson 10's window, for camera paths and
// particles alike. Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md and lessons/10-adrrs/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

float windowContinuations(const Color& beta, const Color& adjoint, float measurement) {
    // TODO(12) Eq. 12.15 with lesson 10's Eq. 10.2, 10.5-10.7: the weight nu of beta with the
    //          adjoint's colour as weights (beta's mean where the adjoint is black), the adjoint as
    //          one number (its channels' mean), then lesson 10's expectedContinuations and
    //          weightWindow with the measurement as I~.
    //          Pitfall: nu times the adjoint's mean is the expected contribution; comparing beta's
    //          largest channel, or the adjoint's sum, shifts every decision.
    (void)beta; (void)adjoint; (void)measurement;
    return PS_TODO("lesson 12: windowContinuations", 1.0f);
}

}  // namespace ps
