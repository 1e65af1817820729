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
    // TODO(10) The pixel estimate I~ of Eq. 10.9, or -1 where the cache cannot give one (adrrs.h).
    (void)cache; (void)scene; (void)x0;
    return PS_TODO("lesson 10: pixelEstimate", -1.0f);
}

float adrrsContinuations(const AdjointCache& cache, const Scene& scene, const WalkVertex& v, float pixelEstimate) {
    // TODO(10) q at v by Eq. 10.2 and 10.5-10.7, or kNoDecision (adrrs.h). Pitfalls (README 6): look the cache up
    //          where the path is; trust only reliable entries.
    (void)cache; (void)scene; (void)v; (void)pixelEstimate;
    return PS_TODO("lesson 10: adrrsContinuations", 1.0f);
}

}  // namespace ps
