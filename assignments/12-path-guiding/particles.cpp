// Lesson 12 — roulette and splitting for particles: the importons a camera path leaves, and a
// particle's decision on their importance. Interface: lessons/12-path-guiding/guiding.h. Equation
// numbers refer to lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

void appendImportons(const std::vector<ImportanceVertex>& path, int pixels, int paths, std::vector<Photon>& out) {
    // TODO(12) Eq. 12.16: for every vertex that stores one, a Photon at p whose power is the
    //          throughput times pixels / paths, and whose direction (setWLight) is wo.
    //          Pitfall: a camera path carries its own pixel's importance; the pass traced
    //          paths / pixels of them per pixel.
    (void)path; (void)pixels; (void)paths; (void)out;
    (void)PS_TODO("lesson 12: appendImportons", 0);
}

Decision particleDecision(const AdjointCache& importance, const Scene& scene, const WalkVertex& y, float imageTotal) {
    // TODO(12) Eq. 12.17: no decision at a miss, a delta material or where y's entry of the
    //          importance cache (the side y.wo sees) is not reliable; else decided, with q from
    //          windowContinuations(y.beta, the albedo times the entry's estimate, imageTotal).
    //          Pitfall: the ideal particle brings the whole image's total, not one pixel's value.
    (void)importance; (void)scene; (void)y; (void)imageTotal;
    return PS_TODO("lesson 12: particleDecision", Decision());
}

}  // namespace ps
