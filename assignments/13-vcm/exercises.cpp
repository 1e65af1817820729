// Lesson 13 — the pen-and-paper exercise. Interface: lessons/13-vcm/exercises.h. Equation numbers
// refer to lessons/13-vcm/README.md ("Exercise (pen and paper)").
#include <cmath>
#include <limits>
#include "13-vcm/exercises.h"
#include "todo.h"

namespace ps {

double halfMergeIteration(const double pdf[3], double pdfLight1, double eta1, double alpha, double b) {
    // TODO(13) i_{1/2} of Eq. 13.E1, with its two limiting cases, as exercises.h states it. Pitfall: the
    //          merge's density multiplies one connection's density (which one, and why?), not their sum.
    (void)pdf; (void)pdfLight1; (void)eta1; (void)alpha; (void)b;
    return PS_TODO("lesson 13: halfMergeIteration (exercise)", 0.0);
}

}  // namespace ps
