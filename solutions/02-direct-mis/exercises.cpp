// Lesson 2 — the pen-and-paper exercise. Interface: lessons/02-direct-mis/exercises.h.
// Equation numbers refer to lessons/02-direct-mis/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "02-direct-mis/exercises.h"
#include "vecmath.h"
#include "todo.h"

namespace ps {

double sphereSolidAngle(double radius, double distance) {
    //! TODO(02) Omega(r, d) of Eq. 2.E1, solved on paper, written so that it stays accurate for r << d (no
    //!          cancellation).
    //! STUB (void)radius; (void)distance;
    //! STUB return PS_TODO("lesson 02: sphereSolidAngle (exercise)", 0.0);
    //! BEGIN
    const double s2 = (radius / distance) * (radius / distance);  // sin^2(theta_max)
    return 2.0 * double(kPi) * s2 / (1.0 + std::sqrt(1.0 - s2));  // 2 pi (1 - cos), no cancellation
    //! END
}

}  // namespace ps
