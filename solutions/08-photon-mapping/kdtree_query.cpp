// Lesson 8 — searching the kd-tree: one traversal, every point within a radius that its visitor
// may shrink (pointsInRadius), and the k nearest points as a bounded max-heap on it that shrinks
// the radius to its k-th distance once full (nearestPoints; Jensen's way). Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

//! BEGIN
namespace {

struct RadiusSearch {
    const KdTree& tree;
    Vec3 x;
    float r2;  // the bound: the caller's radius squared, lowered by the visitor
    const PointVisitor& visit;
    int visited = 0;

    void locate(size_t i) {
        const Vec3& p = tree.p[i];
        const size_t left = 2 * i, n = tree.size();
        if (left <= n) {
            const int axis = tree.axis[i];
            const float delta = x[axis] - p[axis];
            const size_t nearChild = delta > 0.0f ? left + 1 : left, farChild = delta > 0.0f ? left : left + 1;
            if (nearChild <= n) locate(nearChild);
            if (farChild <= n && delta * delta <= r2) locate(farChild);
        }
        ++visited;
        const float d2 = photonDistance2(p, x);
        if (d2 <= r2) visit(uint32_t(i), d2, r2);
    }
};

}  // namespace
//! END

int pointsInRadius(const KdTree& tree, const Vec3& x, float r2, const PointVisitor& visit) {
    //! TODO(08) Every point with d2 <= the bound handed to visit, the bound r2 at first and then whatever visit lowers
    //!          it to (Eq. 8.5; pointsInRadius in photonmap.h); returns the number of nodes visited. Pitfalls
    //!          (README 6): prune with delta^2 against the bound as it is now, not as it was when the search began.
    //! STUB (void)tree; (void)x; (void)r2; (void)visit;
    //! STUB return PS_TODO("lesson 08: pointsInRadius", 0);
    //! BEGIN
    if (tree.size() == 0) return 0;
    RadiusSearch s{tree, x, r2, visit};
    s.locate(1);
    return s.visited;
    //! END
}

int nearestPoints(const KdTree& tree, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found) {
    //! TODO(08) The k nearest points to x within maxD2, in found as a max-heap under nearerPhoton, found by your
    //!          pointsInRadius (Eq. 8.5; nearestPoints in photonmap.h); returns the number of nodes visited. Pitfalls
    //!          (README 6): shrink the bound to found[0].d2 once k are found, not before.
    //! STUB (void)tree; (void)x; (void)k; (void)maxD2;
    //! STUB found.clear();
    //! STUB return PS_TODO("lesson 08: nearestPoints", 0);
    //! BEGIN
    found.clear();
    if (k <= 0) return 0;
    const size_t full = size_t(k);
    found.reserve(full);
    return pointsInRadius(tree, x, maxD2, [&](uint32_t node, float d2, float& r2) {
        if (found.size() == full) {  // the farthest goes: d2 <= r2, its distance
            std::pop_heap(found.begin(), found.end(), nearerPhoton);
            found.pop_back();
        }
        found.push_back({node, d2});
        std::push_heap(found.begin(), found.end(), nearerPhoton);
        if (found.size() == full) r2 = found[0].d2;
    });
    //! END
}

}  // namespace ps
