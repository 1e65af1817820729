// Lesson 9 — primary samples: Kelemen's small step, and the lazy mutation of the chain's state
// with time stamps. Interface: lessons/09-metropolis/pssmlt.h. Equation numbers refer to
// lessons/09-metropolis/README.md.
#include <cmath>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

float smallStep(float v, float uSize, float uSign) {
    // TODO(09) Eq. 9.9: size s2 exp(-ln(s2 / s1) uSize) (kSmallStepMax, kSmallStepMin), added
    //          if uSign < 1/2, else subtracted; wrap into [0, 1) (w - floor(w), and a w that
    //          rounds to 1 is 0).
    (void)uSize; (void)uSign;
    return PS_TODO("lesson 09: smallStep", v);
}

void PrimarySamples::startProposal(bool largeStep) {
    // TODO(09) The next proposal: time one more, remember whether it is a large step, read from
    //          coordinate 0 again.
    (void)largeStep;
    (void)PS_TODO("lesson 09: PrimarySamples::startProposal", 0);
}

float PrimarySamples::next() {
    // TODO(09) Eq. 9.9, lazily: coordinate index_ (grow x_ if the path reads further than ever).
    //          1. It missed the last large step (modified < lastLargeStep_): value = a fresh
    //             rng_.uniform(), modified = lastLargeStep_.
    //          2. Back it up (value and modified), for reject().
    //          3. Large step: value = rng_.uniform(). Small step: the time_ - modified small steps
    //             it missed, one after another, each smallStep(value, uSize, uSign) with uSize then
    //             uSign drawn from rng_.uniform() into variables, in this order (C++ may evaluate a
    //             call's arguments in any order; the tests replay the generator).
    //          4. modified = time_; index_ one more; return the value.
    //          Pitfall: one small step for all the missed ones makes rarely read coordinates
    //          (deep bounces) move too little; no step 1 keeps values from before a large step.
    return PS_TODO("lesson 09: PrimarySamples::next", rng_.uniform());
}

void PrimarySamples::accept() {
    // TODO(09) An accepted large step is now the last large step (lastLargeStep_ = time_).
    (void)PS_TODO("lesson 09: PrimarySamples::accept", 0);
}

void PrimarySamples::reject() {
    // TODO(09) Every coordinate this proposal changed (modified == time_) gets its backup back
    //          (value and modified); then time_ one less: a rejected proposal never happened.
    (void)PS_TODO("lesson 09: PrimarySamples::reject", 0);
}

}  // namespace ps
