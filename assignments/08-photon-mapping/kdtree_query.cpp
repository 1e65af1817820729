// Lesson 8 — searching the kd-tree: the k nearest points with a bounded max-heap, and every point
// within a radius. Interface: lessons/08-photon-mapping/photonmap.h. Equation numbers
// refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {


int nearestPoints(const KdTree& tree, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found) {
    // TODO(08) Eq. 8.5: clear found; nothing to do for an empty tree or k <= 0. From the root
    //          (node 1), recursively at node i: if it has children (2i <= size()), delta = the
    //          difference of x's and the node's coordinate on its axis; search the child on x's
    //          side first (delta > 0: 2i + 1, else 2i), then the other one only if delta^2 <= the
    //          bound (a child index > size() does not exist). Then the node's point itself: count
    //          it as visited, d2 = photonDistance2(its point, x); if d2 <= bound, keep it: fewer
    //          than k found: push_heap; else replace the farthest (pop_heap, overwrite back(),
    //          push_heap), both with nearerPhoton. The bound starts at maxD2 and becomes
    //          found[0].d2 once k are found. Return the number of points visited.
    (void)tree; (void)x; (void)k; (void)maxD2;
    found.clear();
    return PS_TODO("lesson 08: nearestPoints", 0);
}

int pointsInRadius(const KdTree& tree, const Vec3& x, float r2, const PointVisitor& visit) {
    // TODO(08) Eq. 8.5 with a fixed bound: as nearestPoints, handing every point with d2 <= r2 to
    //          visit and visiting the far child only if delta^2 <= r2. Return the number of points
    //          visited.
    (void)tree; (void)x; (void)r2; (void)visit;
    return PS_TODO("lesson 08: pointsInRadius", 0);
}

}  // namespace ps
