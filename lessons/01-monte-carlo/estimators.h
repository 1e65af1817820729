// Lesson 1's estimators: Monte Carlo estimates of an integral, each with the estimated
// variance of that estimate, so a caller can say how far off it may be.
// Implemented in solutions/01-monte-carlo/estimators.cpp (reference) or
// assignments/01-monte-carlo/estimators.cpp (yours); lessons/01-monte-carlo/README.md derives
// every formula (Eq. 1.1-1.5). The random numbers come from the Rng passed in, so a result
// depends only on the generator's state: same seed, same estimate.
#pragma once
#include <functional>
#include <vector>
#include "rng.h"

namespace ps {

// An estimate F of an integral I and the estimated variance of F itself (not of one sample):
// its square root is the standard error, and F +- 3 sqrt(variance) is a ~99.7 % interval.
struct Estimate {
    double value = 0.0;
    double variance = 0.0;
};

namespace mc {
// The sample mean of y_1..y_n (n >= 2) and the estimated variance of that mean (Eq. 1.3): the
// helper every estimator built on independent samples shares (estimators.cpp).
Estimate meanOfSamples(const std::vector<double>& y);
}  // namespace mc

using Function1D = std::function<double(double)>;          // f(x)
using Function2D = std::function<double(double, double)>;  // f(x, y)

// The integral of f over [a, b] from n >= 2 independent uniform samples (Eq. 1.1, 1.3).
Estimate estimatePlain(const Function1D& f, double a, double b, int n, Rng& rng);

// The integral of f over [a, b] with [a, b] cut into n >= 3 equal strata and one uniform
// sample in each (jittered sampling, Eq. 1.4); variance by second differences (Eq. 1.4).
Estimate estimateStratified(const Function1D& f, double a, double b, int n, Rng& rng);

// The integral of f over the domain of a sampler from n >= 2 samples x = sample(u), u uniform
// in [0, 1), each weighted f(x) / pdf(x) (importance sampling, Eq. 1.5). A sample with
// pdf(x) = 0 contributes 0.
Estimate estimateImportance(const Function1D& f, const Function1D& sample, const Function1D& pdf, int n, Rng& rng);

// The integral of f over the unit square [0, 1]^2 from n >= 2 uniform points (Eq. 1.1, 1.3).
Estimate estimatePlain2D(const Function2D& f, int n, Rng& rng);

// The integral of f over the unit square with n x n equal cells (n >= 3), one uniform point in
// each: n^2 samples in all (Eq. 1.4, second differences along x within each row of cells).
Estimate estimateStratified2D(const Function2D& f, int n, Rng& rng);

}  // namespace ps
