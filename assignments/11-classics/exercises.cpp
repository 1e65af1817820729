// Lesson 11 — the pen-and-paper exercise. Interface: lessons/11-classics/exercises.h.
// Equation numbers refer to lessons/11-classics/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "11-classics/exercises.h"
#include "todo.h"

namespace ps {

double diskFormFactor(double R, double h) {
    // TODO(11) Eq. 11.E1: the form factor from a point to a parallel coaxial disk of radius R at
    //          the distance h, integrated over the disk in rings (both cosines are h / r).
    (void)R;
    (void)h;
    return PS_TODO("lesson 11: diskFormFactor (exercise)", 0.0);
}

}  // namespace ps
