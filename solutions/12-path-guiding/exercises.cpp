// Lesson 12 — the pen-and-paper exercise. Interface: lessons/12-path-guiding/exercises.h.
// Equation numbers refer to lessons/12-path-guiding/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "12-path-guiding/exercises.h"
#include "todo.h"

namespace ps {

double guidedVariance(double alpha) {
    //! TODO(12) Var[X] / E[X]^2 of Eq. 12.E1 (exercises.h) as a closed form in alpha, both ends included.
    //! STUB (void)alpha;
    //! STUB return PS_TODO("lesson 12: guidedVariance (exercise)", 0.0);
    //! BEGIN
    const double a = 0.5 * alpha, b = 1.0 - alpha;
    if (b == 0.0) return 1.0 / 3.0;  // the guide alone: E[X^2] / E[X]^2 = 4/3
    if (a == 0.0) return 0.0;        // cosine sampling: zero variance under a uniform sky
    // E[X^2] / E[X]^2 = 2 int_0^1 mu^2 / (a + b mu) dmu
    const double integral = (0.5 * b * b - a * b + a * a * std::log1p(b / a)) / (b * b * b);
    return 2.0 * integral - 1.0;
    //! END
}

}  // namespace ps
