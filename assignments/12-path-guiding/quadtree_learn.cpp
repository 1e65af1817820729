// Lesson 12 — learning the directional distribution: recording a sample and refining the tree
// after a pass. Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

void DirectionalTree::record(const Vec3& w, float value) {
    // TODO(12) One record into the tree (Eq. 12.8; guiding.h). Pitfall (README 6): every level, not only the
    //          leaf; w's point of the square is rescaled to the quadrant at each step.
    (void)w; (void)value;
    (void)PS_TODO("lesson 12: DirectionalTree::record", 0);
}


DirectionalTree DirectionalTree::refined(float rho, int maxDepth) const {
    // TODO(12) The refined tree of Eq. 12.9 (guiding.h), its nodes appended as they are made, the root first.
    //          Pitfall (README 6): the threshold is a share of the whole tree's total, not of the node's.
    (void)rho; (void)maxDepth;
    return PS_TODO("lesson 12: DirectionalTree::refined", *this);
}

}  // namespace ps
