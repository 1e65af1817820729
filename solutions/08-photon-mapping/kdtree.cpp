// Lesson 8 — the kd-tree over a set of points (the photon map's): left-balanced, in arrays in heap order. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include <tuple>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

size_t leftSubtreeSize(size_t n) {
    //! TODO(08) n_left(n) of Eq. 8.4: how many of the n nodes of a left-balanced tree lie in the root's left subtree (0
    //!          for n == 1). Pitfall: a last level more than half full spills into the right subtree.
    //! STUB (void)n;
    //! STUB return PS_TODO("lesson 08: leftSubtreeSize", size_t(0));
    //! BEGIN
    if (n <= 1) return 0;
    size_t full = 1;  // 2^h
    while (full * 2 <= n) full *= 2;
    const size_t half = full / 2;  // 2^(h-1)
    const size_t last = n - (full - 1);
    return (half - 1) + std::min(last, half);
    //! END
}

//! BEGIN
namespace {

// A point and its index in the set, moved as one: the build partitions these in place, so every
// comparison reads two neighbouring entries rather than two points through an index array.
struct Entry {
    Vec3 p;
    uint32_t item;
};

// The total order on one axis: by the axis's coordinate; ties (points on an axis-aligned wall)
// broken by the other two coordinates and then by the point's index. std::nth_element leaves
// equal elements in an order of the standard library's choosing, so without a total order the
// tree, and every image made with it, would differ between libstdc++ and libc++.
inline bool before(const Entry& a, const Entry& b, int axis) {
    if (a.p[axis] < b.p[axis]) return true;
    if (b.p[axis] < a.p[axis]) return false;
    const int second = (axis + 1) % 3, third = (axis + 2) % 3;
    return std::make_tuple(a.p[second], a.p[third], a.item) < std::make_tuple(b.p[second], b.p[third], b.item);
}

// Puts the left-balanced kd-tree of the entries [begin, end) at node `node` of tree (Eq. 8.4).
void balance(Entry* begin, Entry* end, size_t node, KdTree& tree) {
    const size_t n = size_t(end - begin);
    if (n == 0) return;
    int axis = 0;
    if (n > 1) {
        Vec3 lo = begin->p, hi = lo;
        for (const Entry* e = begin + 1; e != end; ++e) {
            lo = glm::min(lo, e->p);
            hi = glm::max(hi, e->p);
        }
        const Vec3 extent = hi - lo;
        axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    }
    Entry* median = begin + leftSubtreeSize(n);
    std::nth_element(begin, median, end, [axis](const Entry& a, const Entry& b) { return before(a, b, axis); });
    tree.p[node] = median->p;
    tree.item[node] = median->item;
    tree.axis[node] = static_cast<uint8_t>(axis);
    balance(begin, median, 2 * node, tree);
    balance(median + 1, end, 2 * node + 1, tree);
}

}  // namespace
//! END

void buildKdTree(const std::vector<Vec3>& points, KdTree& tree) {
    //! TODO(08) The left-balanced kd-tree of the points in tree's arrays, nodes 1..n in heap order (Eq. 8.4; KdTree and
    //!          buildKdTree in photonmap.h); a node without children keeps axis 0. Pitfalls (README 6): index 0 is
    //!          unused; the median's rank is leftSubtreeSize, not n/2; sorting instead of std::nth_element is not O(n
    //!          log n); partitioning indices that point into `points` reads every point through the index (ppm
    //!          rebuilds a tree every pass: move each point with its index instead).
    //! STUB (void)points;
    //! STUB tree = KdTree();
    //! STUB (void)PS_TODO("lesson 08: buildKdTree", 0);
    //! BEGIN
    tree = KdTree();
    if (points.empty()) return;
    const size_t n = points.size();
    tree.p.resize(n + 1);
    tree.item.resize(n + 1);
    tree.axis.resize(n + 1);
    std::vector<Entry> entries(n);
    for (size_t i = 0; i < n; ++i) entries[i] = {points[i], uint32_t(i)};
    balance(entries.data(), entries.data() + n, 1, tree);
    //! END
}

}  // namespace ps
