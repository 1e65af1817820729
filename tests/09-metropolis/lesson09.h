// Shared by lesson 9's graded tests: the one-dimensional targets, the significance level.
#pragma once
#include "alpha.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>
#include "09-metropolis/metropolis1d.h"
#include "format.h"
#include "seed.h"
#include "statistics.h"

namespace lesson09 {

using ps::fmt::num;

// Statistical tests in this suite (every other check is exact or a stated bound):
//   1D: final states of independent chains against f / b (chi-square), 2 targets            -> 2
//   1D: crossings of x = 1/2 per step with local mutations alone (t-test)                      -> 1
//   1D: expected values: plain mean, expected-values mean (t-tests), lower variance (test
//       of equal variances of paired samples, Pitman-Morgan)                                  -> 3
//   PSSMLT: large steps only against the path-traced Cornell box reference (block t-tests)    -> 1
//   PSSMLT: full against the same reference (block t-tests)                                   -> 1
//   PSSMLT: the bootstrap's b against the reference's mean luminance (t-test)                  -> 1
//   MMLT: b_k of path lengths 1-3 against lesson 7's per-length references (z-tests)          -> 1
//   MMLT: against lesson 3's reference (block t-tests)                                         -> 1
// m = 11 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %). A test made of several
// comparisons (the block t-tests, the b_k z-tests) splits its alpha' among them by Sidak again.
constexpr int kStatisticalTests = 11;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

constexpr double kPi = 3.14159265358979323846;

// The lecture's target, f(x) = (x - 1/2)^2, b = 1/12, and its inverse CDF (sampling f / b exactly:
// F(x) = 4 (x - 1/2)^3 + 1/2).
inline double lectureTarget(double x) { return (x - 0.5) * (x - 0.5); }
inline double sampleLectureTarget(double u) { return 0.5 + std::cbrt((u - 0.5) / 4.0); }

// A second target with its integral, so a chain cannot be tuned to the first one: peaked at 1,
// small but positive at 0 (b = (e^3 - 1) / 3).
inline double expTarget(double x) { return std::exp(3.0 * x); }
inline double expTargetIntegral() { return (std::exp(3.0) - 1.0) / 3.0; }

// The local mutation's window [max(0, x - r), min(1, x + r)] (the test's own oracle, Eq. 9.1).
inline double windowLo(double x, double r) { return std::max(0.0, x - r); }
inline double windowHi(double x, double r) { return std::min(1.0, x + r); }
inline double windowLength(double x, double r) { return windowHi(x, r) - windowLo(x, r); }

// The probability per step that a chain of local mutations of radius r (r <= 1/2), started in
// f / b of the lecture's target, crosses x = 1/2: the flux of Eq. 9.3 across it in both directions,
// integrated numerically (midpoint rule, n x n cells per direction; relative error below 1e-6 at
// n = 2000). Left to right: x in [1/2 - r, 1/2], y in [1/2, x + r], pi(x) = 12 (x - 1/2)^2,
// T = 1 / (2r) (full windows), a = min(1, f(y) / f(x)); right to left is its mirror image.
inline double crossingRateByQuadrature(double r, int n = 2000) {
    double flux = 0.0;
    const double hx = r / n;
    for (int i = 0; i < n; ++i) {
        const double x = 0.5 - r + (i + 0.5) * hx, fx = lectureTarget(x);
        const double len = x + r - 0.5, hy = len / n;
        double inner = 0.0;
        for (int j = 0; j < n; ++j) inner += std::min(fx, lectureTarget(0.5 + (j + 0.5) * hy));
        flux += 12.0 / (2.0 * r) * inner * hy * hx;
    }
    return 2.0 * flux;
}

}  // namespace lesson09
