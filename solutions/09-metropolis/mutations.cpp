// Lesson 9 — the one-dimensional mutations and their mixture. Interface:
// lessons/09-metropolis/metropolis1d.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/metropolis1d.h"
#include "todo.h"

namespace ps {

Proposal mutateIndependent(double x, double u) {
    //! TODO(09) Eq. 9.1: y = u, and both densities: a uniform proposal on [0, 1] does not depend on x.
    //! STUB (void)x; (void)u;
    //! STUB return PS_TODO("lesson 09: mutateIndependent", (Proposal{x, 1.0, 1.0}));
    //! BEGIN
    (void)x;
    return Proposal{u, 1.0, 1.0};
    //! END
}

Proposal mutateLocal(double x, double u, double r) {
    //! TODO(09) Eq. 9.1: x's window [max(0, x - r), min(1, x + r)], y = lo + u (hi - lo);
    //!          Txy = 1 / (x's window length), Tyx = 1 / (y's window length).
    //!          Pitfall: clamping x + r (2u - 1) to [0, 1] instead puts mass on 0 and 1, which has
    //!          no density at all.
    //! STUB (void)x; (void)u; (void)r;
    //! STUB return PS_TODO("lesson 09: mutateLocal", (Proposal{x, 1.0, 1.0}));
    //! BEGIN
    const auto window = [r](double s) { return std::min(1.0, s + r) - std::max(0.0, s - r); };
    const double lo = std::max(0.0, x - r), hi = std::min(1.0, x + r);
    const double y = std::min(hi, lo + u * (hi - lo));
    return Proposal{y, 1.0 / window(x), 1.0 / window(y)};
    //! END
}

Proposal mutate(double x, double uSelect, double u, const Mutations& m) {
    //! TODO(09) The mixture: mutateIndependent(x, u) if uSelect < m.pLarge, else mutateLocal(x, u, m.r).
    //! STUB (void)x; (void)uSelect; (void)u; (void)m;
    //! STUB return PS_TODO("lesson 09: mutate", (Proposal{x, 1.0, 1.0}));
    //! BEGIN
    return uSelect < m.pLarge ? mutateIndependent(x, u) : mutateLocal(x, u, m.r);
    //! END
}

}  // namespace ps
