// Lesson 12 — learning the directional distribution: recording a sample and refining the tree
// after a pass. Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

void DirectionalTree::record(const Vec3& w, float value) {
    // TODO(12) Eq. 12.8: add value to the energy of the quadrant that contains w's point of the
    //          square (invertUniformSphere) at every level, from the root down to the leaf, the
    //          point rescaled to the quadrant at every step.
    //          Pitfall: every level, not only the leaf: a quadrant's energy is the sum of the
    //          four below it, and pdf and sample read every level.
    (void)w; (void)value;
    (void)PS_TODO("lesson 12: DirectionalTree::record", 0);
}


DirectionalTree DirectionalTree::refined(float rho, int maxDepth) const {
    // TODO(12) Eq. 12.9: a new tree with the same total: a quadrant whose energy is above rho
    //          times the total (and which is not at maxDepth: the root's quadrants are at depth
    //          1) becomes a node — the old node's quadrants if it had one, else four quadrants of
    //          a quarter of its energy each —, looked at in turn; a quadrant at or below the
    //          threshold is a leaf with its energy. Nodes are appended to `nodes` as they are
    //          made (the root first). A tree with total 0 is returned as it is.
    //          Pitfall: the threshold is a share of the whole tree's total, not of the node's.
    (void)rho; (void)maxDepth;
    return PS_TODO("lesson 12: DirectionalTree::refined", *this);
}

}  // namespace ps
