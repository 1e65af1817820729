// Lesson 6 — the pen-and-paper exercise. Interface: lessons/06-path-space/exercises.h.
// Equation numbers refer to lessons/06-path-space/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "06-path-space/exercises.h"
#include "todo.h"

namespace ps {

double lightTracerPdfK2(double lightArea, const Vec3& x0, const Vec3& n0, const Vec3& x1, const Vec3& n1) {
    //! TODO(06) p_{2,1} of Eq. 6.E1 (exercises.h), solved on paper (Eq. 6.6, 6.8).
    //! STUB (void)lightArea; (void)x0; (void)n0; (void)x1; (void)n1;
    //! STUB return PS_TODO("lesson 06: lightTracerPdfK2 (exercise)", 0.0);
    //! BEGIN
    const double dx = double(x1.x) - x0.x, dy = double(x1.y) - x0.y, dz = double(x1.z) - x0.z;
    const double d2 = dx * dx + dy * dy + dz * dz, d = std::sqrt(d2);
    const double cos0 = (n0.x * dx + n0.y * dy + n0.z * dz) / d;
    const double cos1 = std::abs(n1.x * dx + n1.y * dy + n1.z * dz) / d;
    if (cos0 <= 0.0) return 0.0;
    return (1.0 / lightArea) * (cos0 / double(kPi)) * cos1 / d2;
    //! END
}

}  // namespace ps
