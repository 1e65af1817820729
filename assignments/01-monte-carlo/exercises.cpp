// Lesson 1 — the pen-and-paper exercise. Interface: lessons/01-monte-carlo/exercises.h.
// Equation numbers refer to lessons/01-monte-carlo/README.md ("Exercise (pen and paper)").
#include "01-monte-carlo/exercises.h"
#include "vecmath.h"
#include "todo.h"

namespace ps {

double phongBRDFNormalization(double n) {
    // TODO(01) Eq. 1.E1: solve C(n) * (integral of cos^(n+1)(theta) over the hemisphere) = 1 on
    //          paper (integrate over phi first, then substitute c = cos(theta)) and return C(n).
    (void)n;
    return PS_TODO("lesson 01: phongBRDFNormalization (exercise)", 0.0);
}

}  // namespace ps
