// Lesson 9 — the Metropolis-Hastings acceptance and one step of the chain. Interface:
// lessons/09-metropolis/metropolis1d.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/metropolis1d.h"
#include "todo.h"

namespace ps {

double acceptance(double fx, double fy, const Proposal& p) {
    // TODO(09) Eq. 9.2: a = min(1, f(y) T(y -> x) / (f(x) T(x -> y))).
    //          Pitfall: min(1, f(y) / f(x)) is right only for a symmetric mutation; near the ends of
    //          [0, 1] the local one is not.
    (void)fx; (void)fy; (void)p;
    return PS_TODO("lesson 09: acceptance", 0.0);
}

Step metropolisStep(const Function1D& f, double x, const Mutations& m, Rng& rng) {
    // TODO(09) One step: uSelect, u, then the acceptance number, each rng.uniformDouble(), in
    //          this order (the tests replay them); p = mutate(x, uSelect, u, m),
    //          a = acceptance(f(x), f(p.y), p); next = p.y if the number is < a, else x.
    (void)f; (void)m; (void)rng;
    return PS_TODO("lesson 09: metropolisStep", (Step{x, Proposal{x, 1.0, 1.0}, 0.0}));
}

}  // namespace ps
