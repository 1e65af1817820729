// Lesson 11 — the pen-and-paper exercise. Interface: lessons/11-classics/exercises.h.
// Equation numbers refer to lessons/11-classics/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "11-classics/exercises.h"
#include "todo.h"

namespace ps {

double diskFormFactor(double R, double h) {
    // TODO(11) The form factor of Eq. 11.E1 (exercises.h), integrated on paper.
    (void)R;
    (void)h;
    return PS_TODO("lesson 11: diskFormFactor (exercise)", 0.0);
}

}  // namespace ps
