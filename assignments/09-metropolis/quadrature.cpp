// Lesson 9 — Metropolis quadrature: the normalisation b estimated separately, and the chain's
// plain and expected-values estimates of the integral of g f. Interface:
// lessons/09-metropolis/metropolis1d.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include "09-metropolis/metropolis1d.h"
#include "todo.h"

namespace ps {

double estimateNormalization(const Function1D& f, int n, Rng& rng) {
    // TODO(09) b of Eq. 9.6 from n uniform samples (metropolis1d.h).
    (void)f; (void)n; (void)rng;
    return PS_TODO("lesson 09: estimateNormalization", 0.0);
}

Quadrature metropolisQuadrature(const Function1D& f, const Function1D& g, double b, double x0, int n,
                                const Mutations& m, Rng& rng) {
    // TODO(09) Both estimates of metropolis1d.h from one chain of n steps (Eq. 9.4, 9.5). Pitfall (README 6): the
    //          expected values weigh the state before the step with 1 - a.
    (void)f; (void)g; (void)b; (void)x0; (void)n; (void)m; (void)rng;
    return PS_TODO("lesson 09: metropolisQuadrature", Quadrature{});
}

}  // namespace ps
