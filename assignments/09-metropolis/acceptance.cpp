// Lesson 9 — the Metropolis-Hastings acceptance and one step of the chain. Interface:
// lessons/09-metropolis/metropolis1d.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/metropolis1d.h"
#include "todo.h"

namespace ps {

double acceptance(double fx, double fy, const Proposal& p) {
    // TODO(09) The Metropolis-Hastings acceptance probability of the move (Eq. 9.2). Pitfall (README 6): dropping the
    //          densities is right only for a symmetric mutation; the local one is not, near the ends of [0, 1].
    (void)fx; (void)fy; (void)p;
    return PS_TODO("lesson 09: acceptance", 0.0);
}

Step metropolisStep(const Function1D& f, double x, const Mutations& m, Rng& rng) {
    // TODO(09) One step of the chain from x (metropolis1d.h), drawing its three numbers in the order stated there (the
    //          tests replay them).
    (void)f; (void)m; (void)rng;
    return PS_TODO("lesson 09: metropolisStep", (Step{x, Proposal{x, 1.0, 1.0}, 0.0}));
}

}  // namespace ps
