// Lesson 12 — roulette and splitting for particles: the importons a camera path leaves, and a
// particle's decision on their importance. Interface: lessons/12-path-guiding/guiding.h. Equation
// numbers refer to lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

void appendImportons(const std::vector<ImportanceVertex>& path, int pixels, int paths, std::vector<Photon>& out) {
    // TODO(12) The importons of one camera path (Eq. 12.16; guiding.h). Pitfall: each camera path carries
    //          its own pixel's importance, and the pass traced paths / pixels of them per pixel.
    (void)path; (void)pixels; (void)paths; (void)out;
    (void)PS_TODO("lesson 12: appendImportons", 0);
}

Decision particleDecision(const AdjointCache& importance, const Scene& scene, const WalkVertex& y, float imageTotal) {
    // TODO(12) The decision at particle vertex y (Eq. 12.17; guiding.h), none where the importance cache
    //          cannot say. Pitfall (README 6): the ideal particle brings the whole image's total, not one pixel's.
    (void)importance; (void)scene; (void)y; (void)imageTotal;
    return PS_TODO("lesson 12: particleDecision", Decision());
}

}  // namespace ps
