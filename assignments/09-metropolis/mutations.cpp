// Lesson 9 — the one-dimensional mutations and their mixture. Interface:
// lessons/09-metropolis/metropolis1d.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/metropolis1d.h"
#include "todo.h"

namespace ps {

Proposal mutateIndependent(double x, double u) {
    // TODO(09) The independent proposal of Eq. 9.1 with both densities.
    (void)x; (void)u;
    return PS_TODO("lesson 09: mutateIndependent", (Proposal{x, 1.0, 1.0}));
}

Proposal mutateLocal(double x, double u, double r) {
    // TODO(09) The local proposal of Eq. 9.1 with both densities. Pitfall: clamping x + r (2u - 1) to [0, 1] puts mass
    //          on 0 and 1, which has no density.
    (void)x; (void)u; (void)r;
    return PS_TODO("lesson 09: mutateLocal", (Proposal{x, 1.0, 1.0}));
}

Proposal mutate(double x, double uSelect, double u, const Mutations& m) {
    // TODO(09) The mixture of metropolis1d.h: the chosen mutation's proposal.
    (void)x; (void)uSelect; (void)u; (void)m;
    return PS_TODO("lesson 09: mutate", (Proposal{x, 1.0, 1.0}));
}

}  // namespace ps
