// Lesson 2 — multiple importance sampling: the weights. Interface: lessons/02-direct-mis/mis.h.
// Equation numbers refer to lessons/02-direct-mis/README.md.
#include <algorithm>
#include "02-direct-mis/mis.h"
#include "todo.h"

namespace ps {

float misWeight(Heuristic heuristic, int i, const Technique* techniques, int count) {
    // TODO(02) Return w_i for technique i among techniques[0 .. count-1], with q_k = n_k p_k:
    //            Balance (Eq. 2.7): q_i / sum_k q_k
    //            Power   (Eq. 2.8): q_i^2 / sum_k q_k^2
    //            Maximum (Eq. 2.9): 1 if q_i is the largest q_k (the first one if several tie), else 0
    //          Return 0 when q_i <= 0 (technique i cannot have produced the sample). Divide every
    //          q_k by the largest q_k before squaring (Eq. 2.10): 1e30 squared overflows a float
    //          and 1e-30 squared underflows to 0, and Inf / Inf or 0 / 0 is NaN.
    (void)heuristic; (void)i; (void)techniques; (void)count;
    return PS_TODO("lesson 02: misWeight", 0.0f);
}

}  // namespace ps
