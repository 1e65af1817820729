// Lesson 1 — the pen-and-paper exercise. Interface: lessons/01-monte-carlo/exercises.h.
// Equation numbers refer to lessons/01-monte-carlo/README.md ("Exercise (pen and paper)").
#include "01-monte-carlo/exercises.h"
#include "vecmath.h"
#include "todo.h"

namespace ps {

double phongBRDFNormalization(double n) {
    // TODO(01) C(n) of Eq. 1.E1, solved on paper (README, Exercise); check: n = 0 gives 1 / pi.
    (void)n;
    return PS_TODO("lesson 01: phongBRDFNormalization (exercise)", 0.0);
}

}  // namespace ps
