// Lesson 12 — learning the directional distribution: recording a sample and refining the tree
// after a pass. Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

void DirectionalTree::record(const Vec3& w, float value) {
    //! TODO(12) One record into the tree (Eq. 12.8; guiding.h). Pitfall (README 6): every level, not only the
    //!          leaf; w's point of the square is rescaled to the quadrant at each step.
    //! STUB (void)w; (void)value;
    //! STUB (void)PS_TODO("lesson 12: DirectionalTree::record", 0);
    //! BEGIN
    Vec2 s = invertUniformSphere(w);
    uint32_t node = 0;
    for (;;) {
        const int ix = s.x >= 0.5f ? 1 : 0, iy = s.y >= 0.5f ? 1 : 0, i = ix + 2 * iy;
        QuadNode& q = nodes[node];
        q.energy[i] += value;
        if (q.child[i] == 0) break;
        s = Vec2(2.0f * s.x - float(ix), 2.0f * s.y - float(iy));
        node = q.child[i];
    }
    //! END
}

//! BEGIN
namespace {
// Appends to `out` the refined copy of `node` of `in` (or, for from == 0 with a leaf quadrant, of
// a leaf whose energy is spread evenly) as out's node `at`, at depth `depth` (its quadrants are
// at depth + 1).
void refineNode(const DirectionalTree& in, uint32_t node, bool fromLeaf, const float leafEnergy[4], float threshold,
                int maxDepth, int depth, DirectionalTree& out, uint32_t at) {
    for (int i = 0; i < 4; ++i) {
        const float e = fromLeaf ? leafEnergy[i] : in.nodes[node].energy[i];
        out.nodes[at].energy[i] = e;
        if (!(e > threshold) || depth + 1 >= maxDepth) continue;  // a leaf: what is below it merges
        const uint32_t child = uint32_t(out.nodes.size());
        out.nodes.emplace_back();
        out.nodes[at].child[i] = child;
        const uint32_t inChild = fromLeaf ? 0 : in.nodes[node].child[i];
        if (inChild != 0) {
            refineNode(in, inChild, false, nullptr, threshold, maxDepth, depth + 1, out, child);
        } else {
            const float quarter[4] = {0.25f * e, 0.25f * e, 0.25f * e, 0.25f * e};
            refineNode(in, 0, true, quarter, threshold, maxDepth, depth + 1, out, child);
        }
    }
}
}  // namespace
//! END

DirectionalTree DirectionalTree::refined(float rho, int maxDepth) const {
    //! TODO(12) The refined tree of Eq. 12.9 (guiding.h), its nodes appended as they are made, the root first.
    //!          Pitfall (README 6): the threshold is a share of the whole tree's total, not of the node's.
    //! STUB (void)rho; (void)maxDepth;
    //! STUB return PS_TODO("lesson 12: DirectionalTree::refined", *this);
    //! BEGIN
    const float all = total();
    if (!(all > 0.0f)) return *this;
    DirectionalTree out;
    refineNode(*this, 0, false, nullptr, rho * all, maxDepth, 0, out, 0);
    return out;
    //! END
}

}  // namespace ps
