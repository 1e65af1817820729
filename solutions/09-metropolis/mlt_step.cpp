// Lesson 9 — one Metropolis step of a PSSMLT chain, splatting with expected values. Interface:
// lessons/09-metropolis/pssmlt.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

float mltStep(Chain& chain, float pLarge, Rng& rng, const PathEvaluator& evaluate, const SplatFunction& splat) {
    //! TODO(09) One PSSMLT step of Eq. 9.11 with the expected-values splats of Eq. 9.5, as mltStep in pssmlt.h states
    //!          it, numbers drawn in that order; the proposal is evaluated through an Rng replaying chain.samples
    //!          (framework/rng.h). Pitfall (README 6): each splat is divided by its own I.
    //! STUB (void)chain; (void)pLarge; (void)rng; (void)evaluate; (void)splat;
    //! STUB return PS_TODO("lesson 09: mltStep", 0.0f);
    //! BEGIN
    const bool large = rng.uniform() < pLarge;
    chain.samples.startProposal(large);
    Rng replay;
    replay.replayFrom(&chain.samples);
    const PathSample y = evaluate(replay);
    const PathSample& x = chain.current;
    const float a = std::min(1.0f, y.I / x.I);
    if (a < 1.0f) splat(x.raster, x.L * ((1.0f - a) / x.I));
    if (a > 0.0f) splat(y.raster, y.L * (a / y.I));
    if (rng.uniform() < a) {
        chain.samples.accept();
        chain.current = y;
    } else {
        chain.samples.reject();
    }
    return a;
    //! END
}

}  // namespace ps
