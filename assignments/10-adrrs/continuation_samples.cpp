// Lesson 10 — the pre-pass's samples of the radiance a path collects from each vertex on.
// Interface: lessons/10-adrrs/adrrs.h. Equation numbers refer to lessons/10-adrrs/README.md.
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

void continuationSamples(const std::vector<PrePassVertex>& path, std::vector<CacheSample>& out) {
    // TODO(10) The pre-pass samples of one path (Eq. 10.8; adrrs.h). Pitfall: x_k's own light sample belongs to x_k.
    (void)path; (void)out;
    (void)PS_TODO("lesson 10: continuationSamples", 0);
}

}  // namespace ps
