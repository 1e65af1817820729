// Lesson 8 — the kd-tree over a set of points (the photon map's): left-balanced, in arrays in heap order. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include <tuple>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

size_t leftSubtreeSize(size_t n) {
    // TODO(08) n_left(n) of Eq. 8.4: how many of the n nodes of a left-balanced tree lie in the root's left subtree (0
    //          for n == 1). Pitfall: a last level more than half full spills into the right subtree.
    (void)n;
    return PS_TODO("lesson 08: leftSubtreeSize", size_t(0));
}


void buildKdTree(const std::vector<Vec3>& points, KdTree& tree) {
    // TODO(08) The left-balanced kd-tree of the points in tree's arrays, nodes 1..n in heap order (Eq. 8.4; KdTree and
    //          buildKdTree in photonmap.h); a node without children keeps axis 0. Pitfalls (README 6): index 0 is
    //          unused; the median's rank is leftSubtreeSize, not n/2; sorting instead of std::nth_element is not O(n
    //          log n); partitioning indices that point into `points` reads every point through the index (ppm
    //          rebuilds a tree every pass: move each point with its index instead).
    (void)points;
    tree = KdTree();
    (void)PS_TODO("lesson 08: buildKdTree", 0);
}

}  // namespace ps
