// Lesson 2 — multiple importance sampling: the weights. Interface: lessons/02-direct-mis/mis.h.
// Equation numbers refer to lessons/02-direct-mis/README.md.
#include <algorithm>
#include "02-direct-mis/mis.h"
#include "todo.h"

namespace ps {

float misWeight(Heuristic heuristic, int i, const Technique* techniques, int count) {
    // TODO(02) w_i of techniques[i] among the count given, for the heuristic (Eq. 2.7-2.9, ties as in 2.9), computed
    //          as in Eq. 2.10; 0 when q_i <= 0. Pitfall: a raw pdf squared overflows or underflows a float (1e30,
    //          1e-30), giving NaN.
    (void)heuristic; (void)i; (void)techniques; (void)count;
    return PS_TODO("lesson 02: misWeight", 0.0f);
}

}  // namespace ps
