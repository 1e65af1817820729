// Lesson 8 — the pen-and-paper exercise. Interface: lessons/08-photon-mapping/exercises.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md ("Exercise (pen and paper)").
#include "08-photon-mapping/exercises.h"
#include "todo.h"

namespace ps {

double boxFilterBias(double gx, double gy, double a, double b, double c, double r) {
    // TODO(08) Eq. 8.E1: the mean of E over the disc of radius r, minus E at its centre.
    (void)gx; (void)gy; (void)a; (void)b; (void)c; (void)r;
    return PS_TODO("lesson 08: boxFilterBias (exercise)", 0.0);
}

}  // namespace ps
