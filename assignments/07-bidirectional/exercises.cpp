// Lesson 7 — the pen-and-paper exercise. Interface: lessons/07-bidirectional/exercises.h.
// Equation numbers refer to lessons/07-bidirectional/README.md ("Exercise (pen and paper)").
#include <algorithm>
#include <cmath>
#include "07-bidirectional/exercises.h"
#include "todo.h"

namespace ps {

double techniqueWeightK2(const double pdf[3], int s, double b) {
    // TODO(07) Eq. 7.E1 (exercises.h): Eq. 7.5 for three techniques, safe from overflow and underflow of pdf^b.
    (void)pdf; (void)s; (void)b;
    return PS_TODO("lesson 07: techniqueWeightK2 (exercise)", 0.0);
}

}  // namespace ps
