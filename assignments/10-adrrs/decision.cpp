// Lesson 10 — the ADRRS decision at a vertex: the pixel estimate, the path's weight, the cache's
// prediction and the window. Interface: lessons/10-adrrs/adrrs.h. Equation numbers refer to
// lessons/10-adrrs/README.md.
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

namespace {
// The mean of the three channels (the skeleton does not call it yet: maybe unused).
[[maybe_unused]] float meanOf(const Color& c) { return (c.r + c.g + c.b) / 3.0f; }
}  // namespace

float pixelEstimate(const AdjointCache& cache, const Scene& scene, const WalkVertex& x0) {
    // TODO(10) Eq. 10.9: I~ = the mean of the three channels of the cache's estimate at x0's
    //          entry (cache.entry(x0.sp.p, x0.sp.n, x0.wo)); -1 if x0 is a miss, its material is
    //          delta (scene.materials[x0.sp.material].isDelta()) or the entry's estimate is not
    //          reliable (cache.reliable).
    (void)cache; (void)scene; (void)x0;
    return PS_TODO("lesson 10: pixelEstimate", -1.0f);
}

float adrrsContinuations(const AdjointCache& cache, const Scene& scene, const WalkVertex& v, float pixelEstimate) {
    // TODO(10) Eq. 10.2, 10.5-10.7: where ADRRS cannot decide (pixelEstimate < 0, a delta
    //          material at v, or an estimate at v's entry that is not reliable) return
    //          kNoDecision (lesson 3's roulette then plays). Otherwise, with the cache's estimate
    //          Psi~ at v's entry (cache.entry(v.sp.p, v.sp.n, v.wo)): the path's weight
    //          nu = sum_c beta_c Psi~_c / sum_c Psi~_c (the mean of beta's channels if Psi~ is
    //          black), the adjoint as one number (the mean of Psi~'s channels), and
    //          expectedContinuations(nu, weightWindow(pixelEstimate, adjoint)).
    //          Pitfall: look the cache up where the path IS (v.sp.p, seen from v.wo), not where
    //          it came from.
    (void)cache; (void)scene; (void)v; (void)pixelEstimate;
    return PS_TODO("lesson 10: adrrsContinuations", 1.0f);
}

}  // namespace ps
