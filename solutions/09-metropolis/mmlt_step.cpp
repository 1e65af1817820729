// Lesson 9 — one step of a multiplexed MLT chain: a technique mutation, a large or a small step,
// accepted with the transition probabilities and splatted with expected values. Interface:
// lessons/09-metropolis/mmlt.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include <utility>
#include "09-metropolis/mmlt.h"
#include "todo.h"

namespace ps {

float mmltStep(MultiplexedChain& chain, const MMLTMutations& m, Rng& rng, const SubpathTracer& trace,
               const TechniqueTarget& target, const SplatFunction& splat) {
    //! TODO(09) One MMLT step (Eq. 9.14), as mmltStep in mmlt.h states it, numbers drawn in that order. Pitfalls
    //!          (README 6): the technique mutation's T are not symmetric next to the ends (Eq. 9.13); it traces nothing
    //!          and touches no stream; an accepted large or small step keeps its subpaths.
    //! STUB (void)chain; (void)m; (void)rng; (void)trace; (void)target; (void)splat;
    //! STUB return PS_TODO("lesson 09: mmltStep", 0.0f);
    //! BEGIN
    const float uKind = rng.uniform();
    const PathSample x = chain.current;
    const bool technique = uKind < m.pTechnique;
    const bool large = !technique && uKind < m.pTechnique + m.pLarge;
    int s = chain.s;
    PathSample y;
    float a = 0.0f;
    if (technique) {
        const Proposal p = mutateTechnique(chain.s, chain.k, rng.uniform());
        s = int(p.y);
        y = target(chain.paths, s);
        a = float(acceptance(x.I, y.I, p));
    } else {
        chain.camera.startProposal(large);
        chain.light.startProposal(large);
        if (large) s = selectTechnique(chain.k, rng.uniform());
        Rng camera, light;
        camera.replayFrom(&chain.camera);
        light.replayFrom(&chain.light);
        trace(camera, light, chain.proposed);
        y = target(chain.proposed, s);
        a = std::min(1.0f, y.I / x.I);
    }
    if (a < 1.0f) splat(x.raster, x.L * ((1.0f - a) / x.I));
    if (a > 0.0f) splat(y.raster, y.L * (a / y.I));
    if (rng.uniform() < a) {
        chain.s = s;
        chain.current = y;
        if (!technique) {
            std::swap(chain.paths, chain.proposed);
            chain.camera.accept();
            chain.light.accept();
        }
    } else if (!technique) {
        chain.camera.reject();
        chain.light.reject();
    }
    return a;
    //! END
}

}  // namespace ps
