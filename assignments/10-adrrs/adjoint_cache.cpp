// Lesson 10 — where the adjoint cache keeps a vertex: its grid cell and the side of the surface
// the path sees. Interface: lessons/10-adrrs/adrrs.h. Equation numbers refer to
// lessons/10-adrrs/README.md.
#include <algorithm>
#include <cmath>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

int AdjointCache::cell(const Vec3& p) const {
    // TODO(10) The cell of p (Eq. 10.8), as AdjointCache::cell in adrrs.h states it. Pitfall: clamp after the floor.
    (void)p;
    return PS_TODO("lesson 10: AdjointCache::cell", 0);
}

int AdjointCache::side(const Vec3& n, const Vec3& wo) {
    // TODO(10) The direction bin of a vertex (Eq. 10.8), as AdjointCache::side in adrrs.h states it.
    (void)n; (void)wo;
    return PS_TODO("lesson 10: AdjointCache::side", 0);
}

}  // namespace ps
