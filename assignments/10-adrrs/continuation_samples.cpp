// Lesson 10 — the pre-pass's samples of the radiance a path still collects after each vertex.
// Interface: lessons/10-adrrs/adrrs.h. Equation numbers refer to lessons/10-adrrs/README.md.
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

void continuationSamples(const std::vector<PrePassVertex>& path, std::vector<CacheSample>& out) {
    // TODO(10) Eq. 10.8: for every vertex k of the path with an entry (entry >= 0), append
    //          {entry, value} to out, in the order of the vertices, where value is the sum of
    //          `added` over the vertices AFTER k (j > k), divided by beta_k channel by channel
    //          (a channel where beta_k is 0 gives 0).
    //          Pitfall: x_k's own `added` (its light sample) is not part of it: the walk takes
    //          it before it decides whether to go on.
    (void)path; (void)out;
    (void)PS_TODO("lesson 10: continuationSamples", 0);
}

}  // namespace ps
