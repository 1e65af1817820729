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
    // TODO(09) Eq. 9.13, 9.14: uKind = rng.uniform(); x = chain.current.
    //          Technique mutation (uKind < m.pTechnique): p = mutateTechnique(chain.s, chain.k,
    //          rng.uniform()); y = target(chain.paths, s' = int(p.y)): the same subpaths, no stream
    //          touched; a = acceptance(I(x), I(y), p) (Eq. 9.2 with p's T).
    //          Else large (uKind < m.pTechnique + m.pLarge) or small: startProposal(large) on both
    //          streams; s' = selectTechnique(chain.k, rng.uniform()) if large, else chain.s; two
    //          Rngs replaying chain.camera and chain.light; trace(camera, light, chain.proposed);
    //          y = target(chain.proposed, s'); a = min(1, I(y) / I(x)) (symmetric: no T).
    //          Splat x.L (1 - a) / I(x) at x.raster and y.L a / I(y) at y.raster (weights > 0).
    //          rng.uniform() < a: accept: chain.s = s', chain.current = y, and for a large or
    //          small step chain.paths takes chain.proposed (std::swap) and both streams accept();
    //          else both streams reject() (large or small). Return a.
    //          Pitfall: min(1, I(y) / I(x)) for the technique mutation too: next to the ends its
    //          T are not equal (Eq. 9.13), and the chain visits the end techniques too rarely.
    (void)chain; (void)m; (void)rng; (void)trace; (void)target; (void)splat;
    return PS_TODO("lesson 09: mmltStep", 0.0f);
}

}  // namespace ps
