// Lesson 12 — the density of the directional distribution. Interface:
// lessons/12-path-guiding/guiding.h. Equation numbers refer to lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

float DirectionalTree::pdf(const Vec3& w) const {
    //! TODO(12) The density of w per unit solid angle (Eq. 12.6, 12.5; guiding.h). Pitfalls (README 6): per
    //!          steradian, not per unit area of the square; the point is rescaled to [0, 1)^2 before the next level.
    //! STUB (void)w;
    //! STUB return PS_TODO("lesson 12: DirectionalTree::pdf", 0.0f);
    //! BEGIN
    const float all = total();
    if (!(all > 0.0f)) return uniformSpherePdf();
    Vec2 s = invertUniformSphere(w);
    float density = 1.0f;  // per unit area of the square
    uint32_t node = 0;
    for (;;) {
        const QuadNode& q = nodes[node];
        const int ix = s.x >= 0.5f ? 1 : 0, iy = s.y >= 0.5f ? 1 : 0, i = ix + 2 * iy;
        const float sum = q.energy[0] + q.energy[1] + q.energy[2] + q.energy[3];
        if (!(sum > 0.0f)) return 0.0f;
        density *= 4.0f * q.energy[i] / sum;
        if (q.child[i] == 0 || density == 0.0f) break;
        s = Vec2(2.0f * s.x - float(ix), 2.0f * s.y - float(iy));
        node = q.child[i];
    }
    return density * uniformSpherePdf();
    //! END
}

}  // namespace ps
