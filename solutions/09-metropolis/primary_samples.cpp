// Lesson 9 — primary samples: Kelemen's small step, and the lazy mutation of the chain's state
// with time stamps. Interface: lessons/09-metropolis/pssmlt.h. Equation numbers refer to
// lessons/09-metropolis/README.md.
#include <cmath>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

float smallStep(float v, float uSize, float uSign) {
    //! TODO(09) One small step of v (Eq. 9.9; pssmlt.h), on the torus [0, 1). Pitfall: a value that rounds to 1.
    //! STUB (void)uSize; (void)uSign;
    //! STUB return PS_TODO("lesson 09: smallStep", v);
    //! BEGIN
    const float size = kSmallStepMax * std::exp(-std::log(kSmallStepMax / kSmallStepMin) * uSize);
    float w = uSign < 0.5f ? v + size : v - size;
    w -= std::floor(w);
    return w < 1.0f ? w : 0.0f;
    //! END
}

void PrimarySamples::startProposal(bool largeStep) {
    //! TODO(09) Begin the next proposal (pssmlt.h); next() reads from coordinate 0 again.
    //! STUB (void)largeStep;
    //! STUB (void)PS_TODO("lesson 09: PrimarySamples::startProposal", 0);
    //! BEGIN
    ++time_;
    largeStep_ = largeStep;
    index_ = 0;
    //! END
}

float PrimarySamples::next() {
    //! TODO(09) Coordinate index() of the proposal, brought up to date lazily (Eq. 9.8, 9.9; README 1.7's lazy
    //!          mutation). The tests replay rng_ and the backups: a coordinate that missed the last accepted large step
    //!          first takes a fresh value, dated that step, and only then is backed up for reject(); a small step draws
    //!          uSize before uSign for each missed step. Pitfall (README 6): one step for all the missed ones.
    //! STUB return PS_TODO("lesson 09: PrimarySamples::next", rng_.uniform());
    //! BEGIN
    if (index_ >= x_.size()) x_.resize(index_ + 1);
    Coordinate& c = x_[index_++];
    if (c.modified < lastLargeStep_) {
        c.value = rng_.uniform();
        c.modified = lastLargeStep_;
    }
    c.backup = c.value;
    c.modifiedBackup = c.modified;
    if (largeStep_) c.value = rng_.uniform();
    else
        for (int64_t k = c.modified; k < time_; ++k) {
            const float uSize = rng_.uniform();
            const float uSign = rng_.uniform();
            c.value = smallStep(c.value, uSize, uSign);
        }
    c.modified = time_;
    return c.value;
    //! END
}

void PrimarySamples::accept() {
    //! TODO(09) Keep the proposal (pssmlt.h).
    //! STUB (void)PS_TODO("lesson 09: PrimarySamples::accept", 0);
    //! BEGIN
    if (largeStep_) lastLargeStep_ = time_;
    //! END
}

void PrimarySamples::reject() {
    //! TODO(09) Undo the proposal exactly (pssmlt.h): a rejected proposal never happened (values, their times, the
    //!          time).
    //! STUB (void)PS_TODO("lesson 09: PrimarySamples::reject", 0);
    //! BEGIN
    for (Coordinate& c : x_)
        if (c.modified == time_) {
            c.value = c.backup;
            c.modified = c.modifiedBackup;
        }
    --time_;
    //! END
}

}  // namespace ps
