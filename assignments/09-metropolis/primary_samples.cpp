// Lesson 9 — primary samples: Kelemen's small step, and the lazy mutation of the chain's state
// with time stamps. Interface: lessons/09-metropolis/pssmlt.h. Equation numbers refer to
// lessons/09-metropolis/README.md.
#include <cmath>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

float smallStep(float v, float uSize, float uSign) {
    // TODO(09) One small step of v (Eq. 9.9; pssmlt.h), on the torus [0, 1). Pitfall: a value that rounds to 1.
    (void)uSize; (void)uSign;
    return PS_TODO("lesson 09: smallStep", v);
}

void PrimarySamples::startProposal(bool largeStep) {
    // TODO(09) Begin the next proposal (pssmlt.h); next() reads from coordinate 0 again.
    (void)largeStep;
    (void)PS_TODO("lesson 09: PrimarySamples::startProposal", 0);
}

float PrimarySamples::next() {
    // TODO(09) Coordinate index() of the proposal, brought up to date lazily (Eq. 9.8, 9.9; README 1.7's lazy
    //          mutation). The tests replay rng_ and the backups: a coordinate that missed the last accepted large step
    //          first takes a fresh value, dated that step, and only then is backed up for reject(); a small step draws
    //          uSize before uSign for each missed step. Pitfall (README 6): one step for all the missed ones.
    return PS_TODO("lesson 09: PrimarySamples::next", rng_.uniform());
}

void PrimarySamples::accept() {
    // TODO(09) Keep the proposal (pssmlt.h).
    (void)PS_TODO("lesson 09: PrimarySamples::accept", 0);
}

void PrimarySamples::reject() {
    // TODO(09) Undo the proposal exactly (pssmlt.h): a rejected proposal never happened (values, their times, the
    //          time).
    (void)PS_TODO("lesson 09: PrimarySamples::reject", 0);
}

}  // namespace ps
