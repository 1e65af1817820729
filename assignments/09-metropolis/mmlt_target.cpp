// Lesson 9 — the target of multiplexed MLT: one BPT technique's MIS-weighted contribution over
// the probability of choosing it. Interface: lessons/09-metropolis/mmlt.h. Equation numbers refer
// to lessons/09-metropolis/README.md (lesson 7's to lessons/07-bidirectional/README.md).
#include <algorithm>
#include <cmath>
#include "09-metropolis/mmlt.h"
#include "todo.h"

namespace ps {

float techniqueProbability(int k) {
    // TODO(09) p_k(s) of Eq. 9.12 (mmlt.h).
    (void)k;
    return PS_TODO("lesson 09: techniqueProbability", 0.0f);
}

int selectTechnique(int k, float u) {
    // TODO(09) The technique s of probability p_k(s) (Eq. 9.12) for one number u. Pitfall: u close to 1 may round to k
    //          + 1.
    (void)k; (void)u;
    return PS_TODO("lesson 09: selectTechnique", 0);
}

PathSample multiplexedTarget(const Scene& scene, const SubpathPair& paths, int k, int s) {
    // TODO(09) The chain's target at technique s (Eq. 9.12), as multiplexedTarget in mmlt.h states it; the MIS weight
    //          as in lesson 7's bptSample. Pitfalls (README 6): without the weight the image is about k + 1 times too
    //          bright; without 1 / p_k(s) the bootstrap's b_k is k + 1 times too small; t = 1 lands at the
    //          connection's raster.
    (void)scene; (void)paths; (void)k; (void)s;
    return PS_TODO("lesson 09: multiplexedTarget", PathSample{});
}

}  // namespace ps
