// Lesson 2 — the pen-and-paper exercise. Interface: lessons/02-direct-mis/exercises.h.
// Equation numbers refer to lessons/02-direct-mis/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "02-direct-mis/exercises.h"
#include "vecmath.h"
#include "todo.h"

namespace ps {

double sphereSolidAngle(double radius, double distance) {
    // TODO(02) Omega(r, d) of Eq. 2.E1, solved on paper, written so that it stays accurate for r << d (no
    //          cancellation).
    (void)radius; (void)distance;
    return PS_TODO("lesson 02: sphereSolidAngle (exercise)", 0.0);
}

}  // namespace ps
