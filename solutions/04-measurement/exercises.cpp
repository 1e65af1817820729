// Lesson 4 — the pen-and-paper exercise. Interface: lessons/04-measurement/exercises.h.
// Equation numbers refer to lessons/04-measurement/README.md ("Exercise (pen and paper)").
#include "04-measurement/exercises.h"
#include "todo.h"

namespace ps {

double pinholeImportance(double imageArea, double focalDistance, double cosTheta) {
    //! TODO(04) W_e(theta; A, f) of Eq. 4.E1: Eq. 4.3-4.5 redone with the image plane at distance f.
    //! STUB (void)imageArea; (void)focalDistance; (void)cosTheta;
    //! STUB return PS_TODO("lesson 04: pinholeImportance (exercise)", 0.0);
    //! BEGIN
    const double c2 = cosTheta * cosTheta;
    return focalDistance * focalDistance / (imageArea * c2 * c2);
    //! END
}

}  // namespace ps
