// Lesson 8 — the kd-tree over a set of points (the photon map's): left-balanced, in arrays in heap order. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include <tuple>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

size_t leftSubtreeSize(size_t n) {
    // TODO(08) Eq. 8.4: a left-balanced tree of n nodes has h = floor(log2 n) full levels above
    //          its last one (root at level 0), which holds n - (2^h - 1) nodes packed to the left.
    //          The left subtree has the 2^(h-1) - 1 nodes of its full levels plus
    //          min(n - (2^h - 1), 2^(h-1)) of the last level's. n == 1: 0.
    (void)n;
    return PS_TODO("lesson 08: leftSubtreeSize", size_t(0));
}


void buildKdTree(const std::vector<Vec3>& points, KdTree& tree) {
    // TODO(08) Eq. 8.4: the tree's arrays get n + 1 entries (index 0 unused), then the tree of all
    //          points at node 1, recursively, for the points of a node in one range [begin, end)
    //          of an array of their indices: the axis of largest extent of their bounding box; the
    //          median index m = begin + leftSubtreeSize(end - begin), found with std::nth_element
    //          on that coordinate (O(n) per level, O(n log n) in all; do not sort); the median
    //          point goes to the node with its index and axis, [begin, m) to node 2i, (m, end) to
    //          node 2i + 1. A node without children keeps axis 0. No points: empty arrays.
    (void)points;
    tree = KdTree();
    (void)PS_TODO("lesson 08: buildKdTree", 0);
}

}  // namespace ps
