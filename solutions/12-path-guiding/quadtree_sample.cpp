// Lesson 12 — drawing a direction from the directional distribution. Interface:
// lessons/12-path-guiding/guiding.h. Equation numbers refer to lessons/12-path-guiding/README.md.
#include <algorithm>
#include "12-path-guiding/guiding.h"
#include "todo.h"
#include "warps.h"

namespace ps {

Vec3 DirectionalTree::sample(const Vec2& u) const {
    //! TODO(12) A direction with the density of pdf (Eq. 12.7; guiding.h). Pitfalls: work in double (after
    //!          16 levels a float has no bits left); the leaf's square halves per level: keep its corner and size.
    //! STUB (void)u;
    //! STUB return PS_TODO("lesson 12: DirectionalTree::sample", Vec3(0.0f, 0.0f, 1.0f));
    //! BEGIN
    if (!(total() > 0.0f)) return sampleUniformSphere(u);
    double ux = u.x, uy = u.y;
    double cornerX = 0.0, cornerY = 0.0, size = 1.0;
    uint32_t node = 0;
    for (;;) {
        const QuadNode& q = nodes[node];
        const double left = double(q.energy[0]) + double(q.energy[2]);
        const double right = double(q.energy[1]) + double(q.energy[3]);
        // The column: left with probability left / (left + right).
        const double pLeft = left / (left + right);
        int ix;
        if (ux < pLeft) {
            ix = 0;
            ux = ux / pLeft;
        } else {
            ix = 1;
            ux = (ux - pLeft) / (1.0 - pLeft);
        }
        // The row within that column.
        const double bottom = double(q.energy[ix]), top = double(q.energy[ix + 2]);
        const double pBottom = bottom / (bottom + top);
        int iy;
        if (uy < pBottom) {
            iy = 0;
            uy = uy / pBottom;
        } else {
            iy = 1;
            uy = (uy - pBottom) / (1.0 - pBottom);
        }
        ux = std::min(ux, 1.0 - 1e-12);
        uy = std::min(uy, 1.0 - 1e-12);
        size *= 0.5;
        cornerX += ix * size;
        cornerY += iy * size;
        const int i = ix + 2 * iy;
        if (q.child[i] == 0) break;
        node = q.child[i];
    }
    return sampleUniformSphere(Vec2(float(cornerX + ux * size), float(cornerY + uy * size)));
    //! END
}

}  // namespace ps
