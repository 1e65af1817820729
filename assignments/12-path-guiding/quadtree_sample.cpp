// Lesson 12 — drawing a direction from the directional distribution. Interface:
// lessons/12-path-guiding/guiding.h. Equation numbers refer to lessons/12-path-guiding/README.md.
#include <algorithm>
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

Vec3 DirectionalTree::sample(const Vec2& u) const {
    // TODO(12) Eq. 12.7: from the root, choose a quadrant with probability proportional to its
    //          energy — first the column (x half) with u.x from the two columns' sums, then the
    //          row within it with u.y —, rescale the used number to [0, 1) within the chosen
    //          part, and go on in the quadrant's node until a leaf; the rescaled numbers are the
    //          point within the leaf's square. Map the square's point to the sphere
    //          (sampleUniformSphere). A tree whose total is 0: uniform over the sphere.
    //          Pitfalls: work in double (after 16 levels a float has no bits left); the
    //          leaf's square shrinks by half per level: keep its corner and size.
    (void)u;
    return PS_TODO("lesson 12: DirectionalTree::sample", Vec3(0.0f, 0.0f, 1.0f));
}

}  // namespace ps
