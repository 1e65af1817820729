// Lesson 9 — the one-dimensional mutations and their mixture. Interface:
// lessons/09-metropolis/metropolis1d.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/metropolis1d.h"
#include "todo.h"

namespace ps {

Proposal mutateIndependent(double x, double u) {
    // TODO(09) Eq. 9.1: y = u, and both densities: a uniform proposal on [0, 1] does not depend on x.
    (void)x; (void)u;
    return PS_TODO("lesson 09: mutateIndependent", (Proposal{x, 1.0, 1.0}));
}

Proposal mutateLocal(double x, double u, double r) {
    // TODO(09) Eq. 9.1: x's window [max(0, x - r), min(1, x + r)], y = lo + u (hi - lo);
    //          Txy = 1 / (x's window length), Tyx = 1 / (y's window length).
    //          Pitfall: clamping x + r (2u - 1) to [0, 1] instead puts mass on 0 and 1, which has
    //          no density at all.
    (void)x; (void)u; (void)r;
    return PS_TODO("lesson 09: mutateLocal", (Proposal{x, 1.0, 1.0}));
}

Proposal mutate(double x, double uSelect, double u, const Mutations& m) {
    // TODO(09) The mixture: mutateIndependent(x, u) if uSelect < m.pLarge, else mutateLocal(x, u, m.r).
    (void)x; (void)uSelect; (void)u; (void)m;
    return PS_TODO("lesson 09: mutate", (Proposal{x, 1.0, 1.0}));
}

}  // namespace ps
