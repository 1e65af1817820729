// Lesson 12 — drawing a direction from the directional distribution. Interface:
// lessons/12-path-guiding/guiding.h. Equation numbers refer to lessons/12-path-guiding/README.md.
#include <algorithm>
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

Vec3 DirectionalTree::sample(const Vec2& u) const {
    // TODO(12) A direction with the density of pdf (Eq. 12.7; guiding.h). Pitfalls: work in double (after
    //          16 levels a float has no bits left); the leaf's square halves per level: keep its corner and size.
    (void)u;
    return PS_TODO("lesson 12: DirectionalTree::sample", Vec3(0.0f, 0.0f, 1.0f));
}

}  // namespace ps
