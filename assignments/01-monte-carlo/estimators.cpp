// Lesson 1 — Monte Carlo integration: the estimators. Interface: lessons/01-monte-carlo/estimators.h.
// Equation numbers refer to lessons/01-monte-carlo/README.md. Draw every random number with
// rng.uniformDouble() (uniform in [0, 1) with 53 bits): float's 24 bits are too coarse here.
#include <vector>
#include "01-monte-carlo/estimators.h"
#include "todo.h"

namespace ps {
namespace mc {  // two helpers the five estimators share

// The sample mean of y_1..y_n (n >= 2) and the estimated variance of that mean.
Estimate meanOfSamples(const std::vector<double>& y) {
    // TODO(01) The sample mean and the estimated variance of that mean, with the unbiased s^2 (Eq. 1.3). Pitfall: a
    //          one-pass sum of squares cancels badly (even below 0) when the y_i are nearly equal.
    (void)y;
    return PS_TODO("lesson 01: meanOfSamples", Estimate{});
}

// The sum of the stratum contributions F_k = |stratum| f(x_k), stored row by row with
// `perRow` strata in each row (perRow >= 3), and the estimated variance of that sum.
Estimate sumOfStrata(const std::vector<double>& F, size_t perRow) {
    // TODO(01) The sum of the F_k and its variance by second differences (Eq. 1.4), none across the end of a row.
    (void)F; (void)perRow;
    return PS_TODO("lesson 01: sumOfStrata", Estimate{});
}

}  // namespace mc

Estimate estimatePlain(const Function1D& f, double a, double b, int n, Rng& rng) {
    // TODO(01) The integral over [a, b] by Eq. 1.1 through meanOfSamples; a sample is f over its pdf, not f alone.
    (void)f; (void)a; (void)b; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimatePlain", Estimate{});
}

Estimate estimateStratified(const Function1D& f, double a, double b, int n, Rng& rng) {
    // TODO(01) Eq. 1.4 with n equal strata, one sample each, through sumOfStrata; F_k carries its width.
    (void)f; (void)a; (void)b; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimateStratified", Estimate{});
}

Estimate estimateImportance(const Function1D& f, const Function1D& sample, const Function1D& pdf, int n, Rng& rng) {
    // TODO(01) Eq. 1.5 through meanOfSamples; a sample where the pdf is 0 counts 0 (estimators.h).
    (void)f; (void)sample; (void)pdf; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimateImportance", Estimate{});
}

Estimate estimatePlain2D(const Function2D& f, int n, Rng& rng) {
    // TODO(01) Eq. 1.1 over the unit square (pdf 1) through meanOfSamples.
    (void)f; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimatePlain2D", Estimate{});
}

Estimate estimateStratified2D(const Function2D& f, int n, Rng& rng) {
    // TODO(01) Eq. 1.4 on n x n cells through sumOfStrata, rows along x (estimators.h); F carries its area.
    (void)f; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimateStratified2D", Estimate{});
}

}  // namespace ps
