// Lesson 9 — the pen-and-paper exercise. Interface: lessons/09-metropolis/exercises.h.
// Equation numbers refer to lessons/09-metropolis/README.md ("Exercise (pen and paper)").
#include "09-metropolis/exercises.h"
#include "todo.h"

namespace ps {

double crossingRate(double r) {
    //! TODO(09) Eq. 9.E1: the flux of Eq. 9.3 across x = 1/2, both directions, as a power of r.
    //! STUB (void)r;
    //! STUB return PS_TODO("lesson 09: crossingRate (exercise)", 0.0);
    //! BEGIN
    return r * r * r / 4.0;
    //! END
}

}  // namespace ps
