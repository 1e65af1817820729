// Lesson 10 — the pen-and-paper exercise. Interface: lessons/10-adrrs/exercises.h.
// Equation numbers refer to lessons/10-adrrs/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "10-adrrs/exercises.h"
#include "todo.h"

namespace ps {

double splitVariance(double q) {
    //! TODO(10) Eq. 10.E1: the variance of n beta L / q for beta L = 1 when n is drawn as in
    //!          Eq. 10.4, in terms of q and its fraction f = q - floor(q).
    //! STUB (void)q;
    //! STUB return PS_TODO("lesson 10: splitVariance (exercise)", 0.0);
    //! BEGIN
    const double f = q - std::floor(q);
    return f * (1.0 - f) / (q * q);
    //! END
}

}  // namespace ps
