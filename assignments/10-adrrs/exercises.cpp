// Lesson 10 — the pen-and-paper exercise. Interface: lessons/10-adrrs/exercises.h.
// Equation numbers refer to lessons/10-adrrs/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "10-adrrs/exercises.h"
#include "todo.h"

namespace ps {

double splitVariance(double q) {
    // TODO(10) Var[n beta L / q] of Eq. 10.E1 (exercises.h) as a closed form in q.
    (void)q;
    return PS_TODO("lesson 10: splitVariance (exercise)", 0.0);
}

}  // namespace ps
