// Lesson 12 — the spatial tree: the leaf a point falls in, and where the tree is cut after a
// pass. Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

uint32_t SpatialTree::cellOf(const Vec3& p) const {
    // TODO(12) The cell of p (Eq. 12.10; guiding.h). Pitfall: the box halves along one axis per level; keep
    //          both corners up to date.
    (void)p;
    return PS_TODO("lesson 12: SpatialTree::cellOf", 0u);
}

void SpatialTree::subdivide(std::vector<GuideCell>& cells, uint32_t threshold, size_t maxCells) {
    // TODO(12) Eq. 12.11 over the nodes in index order, new ones included (guiding.h); a cut appends the lower
    //          child first, each child cutting the next axis. Pitfall: take what you need from nodes[i] before
    //          appending (push_back may move the vector).
    (void)cells; (void)threshold; (void)maxCells;
    (void)PS_TODO("lesson 12: SpatialTree::subdivide", 0);
}

}  // namespace ps
