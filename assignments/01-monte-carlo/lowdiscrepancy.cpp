// Lesson 1 — Monte Carlo integration: low-discrepancy points. Interface:
// lessons/01-monte-carlo/lowdiscrepancy.h. Equation numbers refer to lessons/01-monte-carlo/README.md
// (section 1.8). Everything is computed in double: a float holds only 24 bits of an index's digits.
#include <algorithm>
#include <vector>
#include "01-monte-carlo/lowdiscrepancy.h"
#include "todo.h"

namespace ps {

double radicalInverse(uint64_t index, unsigned base) {
    // TODO(01) Phi_b(i) of Eq. 1.15. Pitfalls: indices past 2^32 (all 64 bits count), and the largest indices,
    //          whose exact value lies closer to 1 than a double can: the result must still be < 1.
    (void)index; (void)base;
    return PS_TODO("lesson 01: radicalInverse", 0.0);
}

double halton(uint64_t index, int dimension) {
    // TODO(01) One coordinate of Halton point i (Eq. 1.19). Pitfall: one base for every dimension.
    (void)index; (void)dimension;
    return PS_TODO("lesson 01: halton", 0.0);
}

double cranleyPatterson(double x, double shift) {
    // TODO(01) Eq. 1.20 for one coordinate. Pitfall: x + shift can round to exactly 1.
    (void)shift;
    return PS_TODO("lesson 01: cranleyPatterson", x);
}

Estimate estimateHalton2D(const Function2D& f, int n, int replicates, Rng& rng) {
    // TODO(01) Eq. 1.20, the replicates being the independent samples of Eq. 1.3 (mc::meanOfSamples). Pitfalls: a
    //          shift shared by the replicates; points other than i = 0..n-1.
    (void)f; (void)n; (void)replicates; (void)rng;
    return PS_TODO("lesson 01: estimateHalton2D", Estimate{});
}

}  // namespace ps
