// Lesson 2 — multiple importance sampling: the weights. Interface: lessons/02-direct-mis/mis.h.
// Equation numbers refer to lessons/02-direct-mis/README.md.
#include <algorithm>
#include "02-direct-mis/mis.h"
#include "todo.h"

namespace ps {

float misWeight(Heuristic heuristic, int i, const Technique* techniques, int count) {
    //! TODO(02) Return w_i for technique i among techniques[0 .. count-1], with q_k = n_k p_k:
    //!            Balance (Eq. 2.7): q_i / sum_k q_k
    //!            Power   (Eq. 2.8): q_i^2 / sum_k q_k^2
    //!            Maximum (Eq. 2.9): 1 if q_i is the largest q_k (the first one if several tie), else 0
    //!          Return 0 when q_i <= 0 (technique i cannot have produced the sample). Divide every
    //!          q_k by the largest q_k before squaring (Eq. 2.10): 1e30 squared overflows a float
    //!          and 1e-30 squared underflows to 0, and Inf / Inf or 0 / 0 is NaN.
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
