// Lesson 9 — one Metropolis step of a PSSMLT chain, splatting with expected values. Interface:
// lessons/09-metropolis/pssmlt.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/pssmlt.h"
#include "todo.h"

namespace ps {

float mltStep(Chain& chain, float pLarge, Rng& rng, const PathEvaluator& evaluate, const SplatFunction& splat) {
    // TODO(09) Eq. 9.11: large = rng.uniform() < pLarge; chain.samples.startProposal(large);
    //          evaluate the proposal y with an Rng that replays chain.samples (Rng::replayFrom);
    //          a = min(1, I(y) / I(x)), x = chain.current (the steps are symmetric: no T).
    //          Splat both (Eq. 9.5): x.L (1 - a) / I(x) at x.raster, y.L a / I(y) at y.raster
    //          (only weights > 0). Then rng.uniform() < a: accept (samples and current), else
    //          reject. Return a.
    //          Pitfall: splatting only the state the chain moves to is correct too, but noisier;
    //          splatting L without dividing by I counts bright paths twice (the chain already
    //          visits them more often).
    (void)chain; (void)pLarge; (void)rng; (void)evaluate; (void)splat;
    return PS_TODO("lesson 09: mltStep", 0.0f);
}

}  // namespace ps
