// Lesson 6 — the pen-and-paper exercise. Interface: lessons/06-path-space/exercises.h.
// Equation numbers refer to lessons/06-path-space/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "06-path-space/exercises.h"
#include "todo.h"

namespace ps {

double lightTracerPdfK2(double lightArea, const Vec3& x0, const Vec3& n0, const Vec3& x1, const Vec3& n1) {
    // TODO(06) p_{2,1} of Eq. 6.E1 (exercises.h), solved on paper (Eq. 6.6, 6.8).
    (void)lightArea; (void)x0; (void)n0; (void)x1; (void)n1;
    return PS_TODO("lesson 06: lightTracerPdfK2 (exercise)", 0.0);
}

}  // namespace ps
