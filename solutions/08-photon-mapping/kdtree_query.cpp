// Lesson 8 — searching the kd-tree: the k nearest points with a bounded max-heap, and every point
// within a radius. Interface: lessons/08-photon-mapping/photonmap.h. Equation numbers
// refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

//! BEGIN
namespace {

struct KnnSearch {
    const KdTree& tree;
    Vec3 x;
    size_t k;
    float bound;  // maxD2 until k photons are found, then the farthest one's d2
    std::vector<NearPhoton>& found;
    int visited = 0;

    void locate(size_t i) {
        const Vec3& p = tree.p[i];
        const size_t left = 2 * i, n = tree.size();
        if (left <= n) {
            const int axis = tree.axis[i];
            const float delta = x[axis] - p[axis];
            const size_t nearChild = delta > 0.0f ? left + 1 : left, farChild = delta > 0.0f ? left : left + 1;
            if (nearChild <= n) locate(nearChild);
            if (farChild <= n && delta * delta <= bound) locate(farChild);
        }
        ++visited;
        const float d2 = photonDistance2(p, x);
        if (d2 > bound) return;
        if (found.size() < k) {
            found.push_back({uint32_t(i), d2});
            std::push_heap(found.begin(), found.end(), nearerPhoton);
            if (found.size() == k) bound = found[0].d2;
        } else {
            std::pop_heap(found.begin(), found.end(), nearerPhoton);
            found.back() = {uint32_t(i), d2};
            std::push_heap(found.begin(), found.end(), nearerPhoton);
            bound = found[0].d2;
        }
    }
};

struct RadiusSearch {
    const KdTree& tree;
    Vec3 x;
    float r2;
    const PointVisitor& visit;
    int visited = 0;

    void locate(size_t i) {
        const Vec3& p = tree.p[i];
        const size_t left = 2 * i, n = tree.size();
        if (left <= n) {
            const int axis = tree.axis[i];
            const float delta = x[axis] - p[axis];
            const size_t sameSide = delta > 0.0f ? left + 1 : left, otherSide = delta > 0.0f ? left : left + 1;
            if (sameSide <= n) locate(sameSide);
            if (otherSide <= n && delta * delta <= r2) locate(otherSide);
        }
        ++visited;
        const float d2 = photonDistance2(p, x);
        if (d2 <= r2) visit(uint32_t(i), d2);
    }
};

}  // namespace
//! END

int nearestPoints(const KdTree& tree, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found) {
    //! TODO(08) The k nearest points to x within maxD2, in found as a max-heap under nearerPhoton (Eq. 8.5;
    //!          nearestPoints in photonmap.h); returns the number of nodes visited. Pitfalls (README 6): prune with
    //!          delta^2 against the bound, and shrink the bound to found[0].d2 as soon as k are found.
    //! STUB (void)tree; (void)x; (void)k; (void)maxD2;
    //! STUB found.clear();
    //! STUB return PS_TODO("lesson 08: nearestPoints", 0);
    //! BEGIN
    found.clear();
    if (tree.size() == 0 || k <= 0) return 0;
    found.reserve(size_t(k));
    KnnSearch s{tree, x, size_t(k), maxD2, found};
    s.locate(1);
    return s.visited;
    //! END
}

int pointsInRadius(const KdTree& tree, const Vec3& x, float r2, const PointVisitor& visit) {
    //! TODO(08) Every point with d2 <= r2 handed to visit (Eq. 8.5 with a fixed bound; pointsInRadius in photonmap.h);
    //!          returns the number of nodes visited.
    //! STUB (void)tree; (void)x; (void)r2; (void)visit;
    //! STUB return PS_TODO("lesson 08: pointsInRadius", 0);
    //! BEGIN
    if (tree.size() == 0) return 0;
    RadiusSearch s{tree, x, r2, visit};
    s.locate(1);
    return s.visited;
    //! END
}

}  // namespace ps
