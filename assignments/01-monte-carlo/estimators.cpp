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
    // TODO(01) value = the sample mean Y; variance = s^2 / n with the unbiased sample variance
    //          s^2 = sum_i (y_i - Y)^2 / (n - 1) (Eq. 1.3). Compute Y first, then the squares of
    //          y_i - Y: the shortcut sum y_i^2 - n Y^2 cancels badly when the y_i are nearly
    //          equal (and may even come out negative).
    (void)y;
    return PS_TODO("lesson 01: meanOfSamples", Estimate{});
}

// The sum of the stratum contributions F_k = |stratum| f(x_k), stored row by row with
// `perRow` strata in each row (perRow >= 3), and the estimated variance of that sum.
Estimate sumOfStrata(const std::vector<double>& F, size_t perRow) {
    // TODO(01) value = sum_k F_k (Eq. 1.4). variance: the second differences
    //          d_k = F_{k-1} - 2 F_k + F_{k+1} of three neighbours in the same row (M of them,
    //          perRow - 2 per row); with N = F.size() strata, variance = N / (6 M) * sum_k d_k^2
    //          (Eq. 1.4). Never take a difference across the end of a row.
    (void)F; (void)perRow;
    return PS_TODO("lesson 01: sumOfStrata", Estimate{});
}

}  // namespace mc

Estimate estimatePlain(const Function1D& f, double a, double b, int n, Rng& rng) {
    // TODO(01) n samples x_i = a + (b - a) u_i; the samples of Eq. 1.1 are y_i = (b - a) f(x_i)
    //          (f over the uniform pdf 1 / (b - a)); return mc::meanOfSamples of them.
    (void)f; (void)a; (void)b; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimatePlain", Estimate{});
}

Estimate estimateStratified(const Function1D& f, double a, double b, int n, Rng& rng) {
    // TODO(01) Strata of width h = (b - a) / n; in stratum k one sample x_k = a + (k + u_k) h
    //          and its contribution F_k = h f(x_k) (Eq. 1.4); return mc::sumOfStrata(F, n).
    (void)f; (void)a; (void)b; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimateStratified", Estimate{});
}

Estimate estimateImportance(const Function1D& f, const Function1D& sample, const Function1D& pdf, int n, Rng& rng) {
    // TODO(01) x_i = sample(u_i), y_i = f(x_i) / pdf(x_i), or 0 where pdf(x_i) = 0 (Eq. 1.5);
    //          return mc::meanOfSamples of the y_i.
    (void)f; (void)sample; (void)pdf; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimateImportance", Estimate{});
}

Estimate estimatePlain2D(const Function2D& f, int n, Rng& rng) {
    // TODO(01) Eq. 1.1 on the unit square (area 1, pdf 1): n points (u, v), drawing u before v;
    //          return mc::meanOfSamples of the f(u, v).
    (void)f; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimatePlain2D", Estimate{});
}

Estimate estimateStratified2D(const Function2D& f, int n, Rng& rng) {
    // TODO(01) Cells of side h = 1 / n; cell (i, j) (i along x) gets one point
    //          ((i + u) h, (j + v) h) and the contribution F = h^2 f(point) (Eq. 1.4). Store the
    //          cells row by row (index j n + i, rows along x) and return mc::sumOfStrata(F, n).
    (void)f; (void)n; (void)rng;
    return PS_TODO("lesson 01: estimateStratified2D", Estimate{});
}

}  // namespace ps
