// Lesson 1 — Monte Carlo integration: low-discrepancy points. Interface:
// lessons/01-monte-carlo/lowdiscrepancy.h. Equation numbers refer to lessons/01-monte-carlo/README.md
// (section 1.8). Everything is computed in double: a float holds only 24 bits of an index's digits.
#include <algorithm>
#include <vector>
#include "01-monte-carlo/lowdiscrepancy.h"
#include "todo.h"

namespace ps {

double radicalInverse(uint64_t index, unsigned base) {
    //! TODO(01) Phi_b(i) of Eq. 1.15. Pitfalls: indices past 2^32 (all 64 bits count), and the largest indices,
    //!          whose exact value lies closer to 1 than a double can: the result must still be < 1.
    //! STUB (void)index; (void)base;
    //! STUB return PS_TODO("lesson 01: radicalInverse", 0.0);
    //! BEGIN
    const double invBase = 1.0 / base;
    double value = 0.0, weight = invBase;
    for (uint64_t i = index; i > 0; i /= base, weight *= invBase) value += static_cast<double>(i % base) * weight;
    return std::min(value, 0x1.fffffffffffffp-1);  // the largest double below 1
    //! END
}

double halton(uint64_t index, int dimension) {
    //! TODO(01) One coordinate of Halton point i (Eq. 1.19). Pitfall: one base for every dimension.
    //! STUB (void)index; (void)dimension;
    //! STUB return PS_TODO("lesson 01: halton", 0.0);
    //! BEGIN
    return radicalInverse(index, kHaltonBases[dimension]);
    //! END
}

double cranleyPatterson(double x, double shift) {
    //! TODO(01) Eq. 1.20 for one coordinate. Pitfall: x + shift can round to exactly 1.
    //! STUB (void)shift;
    //! STUB return PS_TODO("lesson 01: cranleyPatterson", x);
    //! BEGIN
    const double y = x + shift;
    return y < 1.0 ? y : y - 1.0;
    //! END
}

Estimate estimateHalton2D(const Function2D& f, int n, int replicates, Rng& rng) {
    //! TODO(01) Eq. 1.20, the replicates being the independent samples of Eq. 1.3 (mc::meanOfSamples). Pitfalls: a
    //!          shift shared by the replicates; points other than i = 0..n-1.
    //! STUB (void)f; (void)n; (void)replicates; (void)rng;
    //! STUB return PS_TODO("lesson 01: estimateHalton2D", Estimate{});
    //! BEGIN
    std::vector<double> y(replicates);
    for (double& v : y) {
        const double sx = rng.uniformDouble(), sy = rng.uniformDouble();
        double sum = 0.0;
        for (int i = 0; i < n; ++i) sum += f(cranleyPatterson(halton(i, 0), sx), cranleyPatterson(halton(i, 1), sy));
        v = sum / n;
    }
    return mc::meanOfSamples(y);
    //! END
}

}  // namespace ps
