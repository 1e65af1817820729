// Lesson 12 — the density of the directional distribution. Interface:
// lessons/12-path-guiding/guiding.h. Equation numbers refer to lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

float DirectionalTree::pdf(const Vec3& w) const {
    // TODO(12) The density of w per unit solid angle (Eq. 12.6, 12.5; guiding.h). Pitfalls (README 6): per
    //          steradian, not per unit area of the square; the point is rescaled to [0, 1)^2 before the next level.
    (void)w;
    return PS_TODO("lesson 12: DirectionalTree::pdf", 0.0f);
}

}  // namespace ps
