// Lesson 10 — where the adjoint cache keeps a vertex: its grid cell and the side of the surface
// the path sees. Interface: lessons/10-adrrs/adrrs.h. Equation numbers refer to
// lessons/10-adrrs/README.md.
#include <algorithm>
#include <cmath>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

int AdjointCache::cell(const Vec3& p) const {
    //! TODO(10) The cell of p (Eq. 10.8), as AdjointCache::cell in adrrs.h states it. Pitfall: clamp after the floor.
    //! STUB (void)p;
    //! STUB return PS_TODO("lesson 10: AdjointCache::cell", 0);
    //! BEGIN
    int i[3];
    for (int a = 0; a < 3; ++a) {
        const float extent = bounds_.hi[a] - bounds_.lo[a];
        const float t = extent > 0.0f ? (p[a] - bounds_.lo[a]) / extent : 0.0f;
        const float f = std::floor(t * float(res_));
        i[a] = f < 0.0f ? 0 : (f >= float(res_ - 1) ? res_ - 1 : int(f));
    }
    return i[0] + res_ * (i[1] + res_ * i[2]);
    //! END
}

int AdjointCache::side(const Vec3& n, const Vec3& wo) {
    //! TODO(10) The direction bin of a vertex (Eq. 10.8), as AdjointCache::side in adrrs.h states it.
    //! STUB (void)n; (void)wo;
    //! STUB return PS_TODO("lesson 10: AdjointCache::side", 0);
    //! BEGIN
    const Vec3 m = dot(n, wo) < 0.0f ? -n : n;
    int a = 0;
    if (std::abs(m.y) > std::abs(m[a])) a = 1;
    if (std::abs(m.z) > std::abs(m[a])) a = 2;
    return 2 * a + (m[a] < 0.0f ? 1 : 0);
    //! END
}

}  // namespace ps
