// Lesson 12 — the pen-and-paper exercise. Interface: lessons/12-path-guiding/exercises.h.
// Equation numbers refer to lessons/12-path-guiding/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "12-path-guiding/exercises.h"
#include "todo.h"

namespace ps {

double guidedVariance(double alpha) {
    // TODO(12) Var[X] / E[X]^2 of Eq. 12.E1 (exercises.h) as a closed form in alpha, both ends included.
    (void)alpha;
    return PS_TODO("lesson 12: guidedVariance (exercise)", 0.0);
}

}  // namespace ps
