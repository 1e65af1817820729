// Lesson 2 — multiple importance sampling: the weights. Interface: lessons/02-direct-mis/mis.h.
// Equation numbers refer to lessons/02-direct-mis/README.md.
#include <algorithm>
#include "02-direct-mis/mis.h"
#include "todo.h"

namespace ps {

float misWeight(Heuristic heuristic, int i, const Technique* techniques, int count) {
    //! TODO(02) w_i of techniques[i] among the count given, for the heuristic (Eq. 2.7-2.9, ties as in 2.9), computed
    //!          as in Eq. 2.10; 0 when q_i <= 0. Pitfall: a raw pdf squared overflows or underflows a float (1e30,
    //!          1e-30), giving NaN.
    //! STUB (void)heuristic; (void)i; (void)techniques; (void)count;
    //! STUB return PS_TODO("lesson 02: misWeight", 0.0f);
    //! BEGIN
    const float qi = techniques[i].n * techniques[i].pdf;
    if (!(qi > 0.0f)) return 0.0f;
    int first = 0;  // the technique with the largest q_k (the first of equals)
    for (int k = 1; k < count; ++k)
        if (techniques[k].n * techniques[k].pdf > techniques[first].n * techniques[first].pdf) first = k;
    if (heuristic == Heuristic::Maximum) return i == first ? 1.0f : 0.0f;
    const float largest = techniques[first].n * techniques[first].pdf;
    float sum = 0.0f, wi = 0.0f;
    for (int k = 0; k < count; ++k) {
        const float r = std::max(0.0f, techniques[k].n * techniques[k].pdf) / largest;  // in [0, 1]
        const float term = heuristic == Heuristic::Power ? r * r : r;
        sum += term;
        if (k == i) wi = term;
    }
    return wi / sum;  // sum >= 1: the largest term is exactly 1
    //! END
}

}  // namespace ps
