// Lesson 9 — the Metropolis-Hastings acceptance and one step of the chain. Interface:
// lessons/09-metropolis/metropolis1d.h. Equation numbers refer to lessons/09-metropolis/README.md.
#include <algorithm>
#include "09-metropolis/metropolis1d.h"
#include "todo.h"

namespace ps {

double acceptance(double fx, double fy, const Proposal& p) {
    //! TODO(09) The Metropolis-Hastings acceptance probability of the move (Eq. 9.2). Pitfall (README 6): dropping the
    //!          densities is right only for a symmetric mutation; the local one is not, near the ends of [0, 1].
    //! STUB (void)fx; (void)fy; (void)p;
    //! STUB return PS_TODO("lesson 09: acceptance", 0.0);
    //! BEGIN
    return std::min(1.0, fy * p.Tyx / (fx * p.Txy));
    //! END
}

Step metropolisStep(const Function1D& f, double x, const Mutations& m, Rng& rng) {
    //! TODO(09) One step of the chain from x (metropolis1d.h), drawing its three numbers in the order stated there (the
    //!          tests replay them).
    //! STUB (void)f; (void)m; (void)rng;
    //! STUB return PS_TODO("lesson 09: metropolisStep", (Step{x, Proposal{x, 1.0, 1.0}, 0.0}));
    //! BEGIN
    const double uSelect = rng.uniformDouble();
    const double u = rng.uniformDouble();
    const double uAccept = rng.uniformDouble();
    Step s;
    s.p = mutate(x, uSelect, u, m);
    s.a = acceptance(f(x), f(s.p.y), s.p);
    s.next = uAccept < s.a ? s.p.y : x;
    return s;
    //! END
}

}  // namespace ps
