// Lesson 12 — the spatial tree: the leaf a point falls in, and where the tree is cut after a
// pass. Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

uint32_t SpatialTree::cellOf(const Vec3& p) const {
    //! TODO(12) The cell of p (Eq. 12.10; guiding.h). Pitfall: the box halves along one axis per level; keep
    //!          both corners up to date.
    //! STUB (void)p;
    //! STUB return PS_TODO("lesson 12: SpatialTree::cellOf", 0u);
    //! BEGIN
    Vec3 lo = bounds_.lo, hi = bounds_.hi;
    uint32_t node = 0;
    while (!nodes[node].isLeaf()) {
        const int a = nodes[node].axis;
        const float middle = 0.5f * (lo[a] + hi[a]);
        if (p[a] >= middle) {
            lo[a] = middle;
            node = nodes[node].child[1];
        } else {
            hi[a] = middle;
            node = nodes[node].child[0];
        }
    }
    return nodes[node].cell;
    //! END
}

void SpatialTree::subdivide(std::vector<GuideCell>& cells, uint32_t threshold, size_t maxCells) {
    //! TODO(12) Eq. 12.11 over the nodes in index order, new ones included (guiding.h); a cut appends the lower
    //!          child first, each child cutting the next axis. Pitfall: take what you need from nodes[i] before
    //!          appending (push_back may move the vector).
    //! STUB (void)cells; (void)threshold; (void)maxCells;
    //! STUB (void)PS_TODO("lesson 12: SpatialTree::subdivide", 0);
    //! BEGIN
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (!nodes[i].isLeaf() || cells[nodes[i].cell].samples <= threshold) continue;
        if (cells.size() >= maxCells) return;
        const uint32_t cell = nodes[i].cell;
        const uint8_t next = uint8_t((nodes[i].axis + 1) % 3);
        cells[cell].samples /= 2;
        const uint32_t upperCell = uint32_t(cells.size());
        cells.push_back(cells[cell]);
        SpatialNode lower, upper;
        lower.axis = upper.axis = next;
        lower.cell = cell;
        upper.cell = upperCell;
        const uint32_t first = uint32_t(nodes.size());
        nodes.push_back(lower);
        nodes.push_back(upper);
        nodes[i].child[0] = first;
        nodes[i].child[1] = first + 1;
    }
    //! END
}

}  // namespace ps
