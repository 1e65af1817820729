// Lesson 4 — the pen-and-paper exercise. Interface: lessons/04-measurement/exercises.h.
// Equation numbers refer to lessons/04-measurement/README.md ("Exercise (pen and paper)").
#include "04-measurement/exercises.h"
#include "todo.h"

namespace ps {

double pinholeImportance(double imageArea, double focalDistance, double cosTheta) {
    // TODO(04) Eq. 4.E1: redo Eq. 4.3-4.5 with the image plane at distance f instead of 1
    //          (the point on the plane is at r = f / cos(theta)).
    (void)imageArea; (void)focalDistance; (void)cosTheta;
    return PS_TODO("lesson 04: pinholeImportance (exercise)", 0.0);
}

}  // namespace ps
