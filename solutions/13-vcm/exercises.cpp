// Lesson 13 — the pen-and-paper exercise. Interface: lessons/13-vcm/exercises.h. Equation numbers
// refer to lessons/13-vcm/README.md ("Exercise (pen and paper)").
#include <cmath>
#include <limits>
#include "13-vcm/exercises.h"
#include "todo.h"

namespace ps {

double halfMergeIteration(const double pdf[3], double pdfLight1, double eta1, double alpha, double b) {
    //! TODO(13) i_{1/2} of Eq. 13.E1, with its two limiting cases, as exercises.h states it. Pitfall: the
    //!          merge's density multiplies one connection's density (which one, and why?), not their sum.
    //! STUB (void)pdf; (void)pdfLight1; (void)eta1; (void)alpha; (void)b;
    //! STUB return PS_TODO("lesson 13: halfMergeIteration (exercise)", 0.0);
    //! BEGIN
    const double others = std::pow(std::pow(pdf[0], b) + std::pow(pdf[1], b) + std::pow(pdf[2], b), 1.0 / b);
    const double merge1 = eta1 * pdfLight1 * pdf[1];  // eta_1 p_L(x_1) p_1, the merge's density at i = 1
    if (merge1 <= others) return 1.0;
    if (alpha >= 1.0) return std::numeric_limits<double>::infinity();
    return std::pow(merge1 / others, 1.0 / (1.0 - alpha));
    //! END
}

}  // namespace ps
