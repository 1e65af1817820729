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
    //! TODO(01) The sample mean and the estimated variance of that mean, with the unbiased s^2 (Eq. 1.3). Pitfall: a
    //!          one-pass sum of squares cancels badly (even below 0) when the y_i are nearly equal.
    //! STUB (void)y;
    //! STUB return PS_TODO("lesson 01: meanOfSamples", Estimate{});
    //! BEGIN
    const double n = static_cast<double>(y.size());
    double mean = 0.0;
    for (double v : y) mean += v;
    mean /= n;
    double squares = 0.0;
    for (double v : y) squares += (v - mean) * (v - mean);
    return {mean, squares / (n - 1.0) / n};
    //! END
}

// The sum of the stratum contributions F_k = |stratum| f(x_k), stored row by row with
// `perRow` strata in each row (perRow >= 3), and the estimated variance of that sum.
Estimate sumOfStrata(const std::vector<double>& F, size_t perRow) {
    //! TODO(01) The sum of the F_k and its variance by second differences (Eq. 1.4), none across the end of a row.
    //! STUB (void)F; (void)perRow;
    //! STUB return PS_TODO("lesson 01: sumOfStrata", Estimate{});
    //! BEGIN
    double sum = 0.0, squares = 0.0;
    size_t M = 0;
    for (double v : F) sum += v;
    for (size_t row = 0; row < F.size(); row += perRow)
        for (size_t k = row + 1; k + 1 < row + perRow; ++k, ++M) {
            const double d = F[k - 1] - 2.0 * F[k] + F[k + 1];
            squares += d * d;
        }
    return {sum, static_cast<double>(F.size()) / (6.0 * static_cast<double>(M)) * squares};
    //! END
}

}  // namespace mc

Estimate estimatePlain(const Function1D& f, double a, double b, int n, Rng& rng) {
    //! TODO(01) The integral over [a, b] by Eq. 1.1 through meanOfSamples; a sample is f over its pdf, not f alone.
    //! STUB (void)f; (void)a; (void)b; (void)n; (void)rng;
    //! STUB return PS_TODO("lesson 01: estimatePlain", Estimate{});
    //! BEGIN
    std::vector<double> y(n);
    for (double& v : y) v = (b - a) * f(a + (b - a) * rng.uniformDouble());
    return mc::meanOfSamples(y);
    //! END
}

Estimate estimateStratified(const Function1D& f, double a, double b, int n, Rng& rng) {
    //! TODO(01) Eq. 1.4 with n equal strata, one sample each, through sumOfStrata; F_k carries its width.
    //! STUB (void)f; (void)a; (void)b; (void)n; (void)rng;
    //! STUB return PS_TODO("lesson 01: estimateStratified", Estimate{});
    //! BEGIN
    const double h = (b - a) / n;
    std::vector<double> F(n);
    for (int k = 0; k < n; ++k) F[k] = h * f(a + (k + rng.uniformDouble()) * h);
    return mc::sumOfStrata(F, n);
    //! END
}

Estimate estimateImportance(const Function1D& f, const Function1D& sample, const Function1D& pdf, int n, Rng& rng) {
    //! TODO(01) Eq. 1.5 through meanOfSamples; a sample where the pdf is 0 counts 0 (estimators.h).
    //! STUB (void)f; (void)sample; (void)pdf; (void)n; (void)rng;
    //! STUB return PS_TODO("lesson 01: estimateImportance", Estimate{});
    //! BEGIN
    std::vector<double> y(n);
    for (double& v : y) {
        const double x = sample(rng.uniformDouble()), p = pdf(x);
        v = p > 0.0 ? f(x) / p : 0.0;
    }
    return mc::meanOfSamples(y);
    //! END
}

Estimate estimatePlain2D(const Function2D& f, int n, Rng& rng) {
    //! TODO(01) Eq. 1.1 over the unit square (pdf 1) through meanOfSamples.
    //! STUB (void)f; (void)n; (void)rng;
    //! STUB return PS_TODO("lesson 01: estimatePlain2D", Estimate{});
    //! BEGIN
    std::vector<double> y(n);
    for (double& v : y) {
        const double x = rng.uniformDouble();
        v = f(x, rng.uniformDouble());
    }
    return mc::meanOfSamples(y);
    //! END
}

Estimate estimateStratified2D(const Function2D& f, int n, Rng& rng) {
    //! TODO(01) Eq. 1.4 on n x n cells through sumOfStrata, rows along x (estimators.h); F carries its area.
    //! STUB (void)f; (void)n; (void)rng;
    //! STUB return PS_TODO("lesson 01: estimateStratified2D", Estimate{});
    //! BEGIN
    const double h = 1.0 / n;
    std::vector<double> F(static_cast<size_t>(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = (i + rng.uniformDouble()) * h;
            F[static_cast<size_t>(j) * n + i] = h * h * f(x, (j + rng.uniformDouble()) * h);
        }
    return mc::sumOfStrata(F, n);
    //! END
}

}  // namespace ps
