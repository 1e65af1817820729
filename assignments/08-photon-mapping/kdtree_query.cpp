// Lesson 8 — searching the kd-tree: one traversal, every point within a radius that its visitor
// may shrink (pointsInRadius), and the k nearest points as a bounded max-heap on it that shrinks
// the radius to its k-th distance once full (nearestPoints; Jensen's way). Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {


int pointsInRadius(const KdTree& tree, const Vec3& x, float r2, const PointVisitor& visit) {
    // TODO(08) Every point with d2 <= the bound handed to visit, the bound r2 at first and then whatever visit lowers
    //          it to (Eq. 8.5; pointsInRadius in photonmap.h); returns the number of nodes visited. Pitfalls
    //          (README 6): prune with delta^2 against the bound as it is now, not as it was when the search began.
    (void)tree; (void)x; (void)r2; (void)visit;
    return PS_TODO("lesson 08: pointsInRadius", 0);
}

int nearestPoints(const KdTree& tree, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found) {
    // TODO(08) The k nearest points to x within maxD2, in found as a max-heap under nearerPhoton, found by your
    //          pointsInRadius (Eq. 8.5; nearestPoints in photonmap.h); returns the number of nodes visited. Pitfalls
    //          (README 6): shrink the bound to found[0].d2 once k are found, not before.
    (void)tree; (void)x; (void)k; (void)maxD2;
    found.clear();
    return PS_TODO("lesson 08: nearestPoints", 0);
}

}  // namespace ps
