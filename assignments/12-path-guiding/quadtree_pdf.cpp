// Lesson 12 — the density of the directional distribution. Interface:
// lessons/12-path-guiding/guiding.h. Equation numbers refer to lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

float DirectionalTree::pdf(const Vec3& w) const {
    // TODO(12) Eq. 12.6 and 12.5: the density of w per unit solid angle. From the root, follow
    //          the quadrants that contain s = invertUniformSphere(w): at each node the density
    //          per unit area of the square is multiplied by 4 times the quadrant's share of the
    //          node's energy; the leaf ends it. A tree whose total is 0 is uniform.
    //          Pitfalls: the result is per steradian, not per unit area of the square (Eq. 12.5);
    //          a quadrant's point is rescaled to [0, 1)^2 before the next level.
    (void)w;
    return PS_TODO("lesson 12: DirectionalTree::pdf", 0.0f);
}

}  // namespace ps
