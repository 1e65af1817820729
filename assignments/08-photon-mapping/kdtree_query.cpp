// Lesson 8 — searching the kd-tree: the k nearest points with a bounded max-heap, and every point
// within a radius. Interface: lessons/08-photon-mapping/photonmap.h. Equation numbers
// refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {


int nearestPoints(const KdTree& tree, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found) {
    // TODO(08) The k nearest points to x within maxD2, in found as a max-heap under nearerPhoton (Eq. 8.5;
    //          nearestPoints in photonmap.h); returns the number of nodes visited. Pitfalls (README 6): prune with
    //          delta^2 against the bound, and shrink the bound to found[0].d2 as soon as k are found.
    (void)tree; (void)x; (void)k; (void)maxD2;
    found.clear();
    return PS_TODO("lesson 08: nearestPoints", 0);
}

int pointsInRadius(const KdTree& tree, const Vec3& x, float r2, const PointVisitor& visit) {
    // TODO(08) Every point with d2 <= r2 handed to visit (Eq. 8.5 with a fixed bound; pointsInRadius in photonmap.h);
    //          returns the number of nodes visited.
    (void)tree; (void)x; (void)r2; (void)visit;
    return PS_TODO("lesson 08: pointsInRadius", 0);
}

}  // namespace ps
