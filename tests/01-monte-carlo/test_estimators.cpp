// Lesson 1, graded: the estimators (lessons/01-monte-carlo/estimators.h; Eq. 1.1-1.5 of the
// lesson README). Each is run many times with independent generators (stream = run index):
// the mean of the runs must be the known integral (t-test with a power check), the variance it
// reports must be the variance the runs really have, stratification must beat plain sampling,
// and importance sampling with a pdf proportional to f must have no variance at all.
#include <doctest/doctest.h>
#include <cmath>
#include "01-monte-carlo/estimators.h"
#include "lesson01.h"
#include "seed.h"

using namespace lesson01;
using ps::Estimate;

namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kE = 2.71828182845904523536;

struct Integral1D {
    const char* name;
    ps::Function1D f;
    double a, b, value;
};
const Integral1D kSquare{"x^2 over [0, 1]", [](double x) { return x * x; }, 0.0, 1.0, 1.0 / 3.0};
const Integral1D kSine{"sin(x) over [0, pi]", [](double x) { return std::sin(x); }, 0.0, kPiD, 2.0};

// x e^(xy) over the unit square: the inner integral over y is e^x - 1, so I = e - 2.
const ps::Function2D kSquare2D = [](double x, double y) { return x * std::exp(x * y); };
constexpr double kSquare2DValue = kE - 2.0;

// Runs an estimator `runs` times, run r with Rng(seed, r).
template <class Run>
std::vector<Estimate> repeat(int runs, uint64_t seed, const Run& run) {
    std::vector<Estimate> out;
    for (int r = 0; r < runs; ++r) {
        ps::Rng rng(ps::testseed::seed(seed), uint64_t(r));
        out.push_back(run(rng));
    }
    return out;
}

// t-test of the runs' mean against the integral; the power check demands a standard error of at
// most 0.5 % of the integral, so a noisy or degenerate estimator cannot pass for lack of evidence.
template <class Run>
void checkUnbiased(const std::string& what, double reference, uint64_t seed, const Run& run) {
    ps::stats::Welford w;
    for (const Estimate& e : repeat(100, seed, run)) w.add(e.value);
    const ps::stats::TTestResult t = ps::stats::tTest(w, reference, alpha(), 0.005);
    CHECK_MESSAGE(t.passed, what << " (100 independent runs): expected " << reference << ", got " << t.mean << " +- "
                                 << t.stdError << ". " << t.report);
}

struct Spread {
    double empirical = 0.0, reported = 0.0;  // variance of the values; mean reported variance
};
template <class Run>
Spread spread(int runs, uint64_t seed, const Run& run) {
    ps::stats::Welford values;
    double reported = 0.0;
    for (const Estimate& e : repeat(runs, seed, run)) {
        values.add(e.value);
        reported += e.variance;
    }
    return {values.variance(), reported / runs};
}

// The mean reported variance against the variance of 4000 independent estimates. The sample
// variance of 4000 near-normal values has a relative standard deviation of sqrt(2 / 3999) ~
// 2.2 %, so +- 12 % is more than 5 standard deviations: a correct estimator does not fail by
// chance. (The stratified estimate of Eq. 1.4 is low by O(1/n) where the strata's variances
// differ, from the strata at the ends of a row: ~1-3 % here.)
template <class Run>
void checkReportedVariance(const std::string& what, uint64_t seed, const Run& run) {
    const Spread s = spread(4000, seed, run);
    const double ratio = s.reported / s.empirical;
    CHECK_MESSAGE((s.empirical > 0.0 && std::isfinite(ratio) && std::abs(ratio - 1.0) < 0.12),
                  what << ": the variance of 4000 independent estimates is " << s.empirical
                       << ", the estimator reports " << s.reported << " on average (ratio " << ratio
                       << ", expected 1 +- 0.12)");
}

// Importance sampling of x^2 on [0, 1] with pdf 2x (x = sqrt(u)) and of x e^-x on [0, inf) with
// pdf e^-x (x = -log(1 - u)): f / pdf = x / 2 and x, integrals 1/3 and 1.
const ps::Function1D kSqrt = [](double u) { return std::sqrt(u); };
const ps::Function1D kLinearPdf = [](double x) { return x >= 0.0 && x <= 1.0 ? 2.0 * x : 0.0; };
const ps::Function1D kXExp = [](double x) { return x * std::exp(-x); };
const ps::Function1D kExpSample = [](double u) { return -std::log1p(-u); };
const ps::Function1D kExpPdf = [](double x) { return x >= 0.0 ? std::exp(-x) : 0.0; };

}  // namespace

TEST_CASE("estimators: plain Monte Carlo is unbiased (t-test) [2 pts]") {
    for (const Integral1D& I : {kSquare, kSine})
        checkUnbiased(std::string("plain, ") + I.name + ", n = 1000", I.value, 201,
                      [&](ps::Rng& rng) { return ps::estimatePlain(I.f, I.a, I.b, 1000, rng); });
}

TEST_CASE("estimators: stratified sampling is unbiased (t-test) [2 pts]") {
    for (const Integral1D& I : {kSquare, kSine})
        checkUnbiased(std::string("stratified, ") + I.name + ", n = 1000", I.value, 202,
                      [&](ps::Rng& rng) { return ps::estimateStratified(I.f, I.a, I.b, 1000, rng); });
}

TEST_CASE("estimators: importance sampling is unbiased (t-test) [1 pt]") {
    checkUnbiased("importance, x^2 over [0, 1] with pdf 2x, n = 1000", 1.0 / 3.0, 203,
                  [&](ps::Rng& rng) { return ps::estimateImportance(kSquare.f, kSqrt, kLinearPdf, 1000, rng); });
    checkUnbiased("importance, x e^-x over [0, inf) with pdf e^-x, n = 1000", 1.0, 204,
                  [&](ps::Rng& rng) { return ps::estimateImportance(kXExp, kExpSample, kExpPdf, 1000, rng); });
}

TEST_CASE("estimators: 2D plain and stratified are unbiased (t-test) [2 pts]") {
    checkUnbiased("plain 2D, x e^(xy) over [0, 1]^2, n = 1024", kSquare2DValue, 205,
                  [&](ps::Rng& rng) { return ps::estimatePlain2D(kSquare2D, 1024, rng); });
    checkUnbiased("stratified 2D, x e^(xy) over [0, 1]^2, 32 x 32 cells", kSquare2DValue, 206,
                  [&](ps::Rng& rng) { return ps::estimateStratified2D(kSquare2D, 32, rng); });
}

TEST_CASE("estimators: reported variance matches the variance over independent runs [2 pts]") {
    checkReportedVariance("plain, sin(x) over [0, pi], n = 100", 301,
                          [&](ps::Rng& rng) { return ps::estimatePlain(kSine.f, kSine.a, kSine.b, 100, rng); });
    checkReportedVariance("stratified, sin(x) over [0, pi], n = 200", 302,
                          [&](ps::Rng& rng) { return ps::estimateStratified(kSine.f, kSine.a, kSine.b, 200, rng); });
    checkReportedVariance("importance, x e^-x with pdf e^-x, n = 100", 303,
                          [&](ps::Rng& rng) { return ps::estimateImportance(kXExp, kExpSample, kExpPdf, 100, rng); });
    checkReportedVariance("plain 2D, x e^(xy), n = 100", 304,
                          [&](ps::Rng& rng) { return ps::estimatePlain2D(kSquare2D, 100, rng); });
    checkReportedVariance("stratified 2D, x e^(xy), 32 x 32 cells", 305,
                          [&](ps::Rng& rng) { return ps::estimateStratified2D(kSquare2D, 32, rng); });
}

TEST_CASE("estimators: stratified variance is far below plain variance at equal n [1 pt]") {
    // Theory (Eq. 1.4): for smooth f and N samples the stratified variance falls as N^-3 in 1D
    // and N^-2 in 2D (n x n = N cells), the plain one as N^-1: at 64 samples the ratio is ~3000
    // for x^2 in 1D and ~50 for x e^(xy) with 8 x 8 cells. The test asks for 100 and 5.
    struct Case {
        std::string what;
        Spread plain, stratified;
        double factor;
    };
    const Case cases[] = {
        {"x^2 over [0, 1], n = 64",
         spread(1000, 401, [](ps::Rng& rng) { return ps::estimatePlain(kSquare.f, 0.0, 1.0, 64, rng); }),
         spread(1000, 402, [](ps::Rng& rng) { return ps::estimateStratified(kSquare.f, 0.0, 1.0, 64, rng); }), 100.0},
        {"x e^(xy) over [0, 1]^2, 64 samples (8 x 8 cells)",
         spread(1000, 403, [](ps::Rng& rng) { return ps::estimatePlain2D(kSquare2D, 64, rng); }),
         spread(1000, 404, [](ps::Rng& rng) { return ps::estimateStratified2D(kSquare2D, 8, rng); }), 5.0},
    };
    for (const Case& c : cases) {
        CHECK_MESSAGE((c.plain.empirical > 0.0 && c.stratified.empirical * c.factor < c.plain.empirical),
                      c.what << ": variance over 1000 runs: plain " << c.plain.empirical << ", stratified "
                             << c.stratified.empirical << "; expected stratified < plain / " << c.factor);
        CHECK_MESSAGE((c.plain.reported > 0.0 && c.stratified.reported * c.factor < c.plain.reported),
                      c.what << ": reported variance (mean over 1000 runs): plain " << c.plain.reported
                             << ", stratified " << c.stratified.reported << "; expected stratified < plain / "
                             << c.factor);
    }
}

TEST_CASE("estimators: importance sampling with pdf proportional to f has zero variance [1 pt]") {
    // pdf = f / I makes every sample f / pdf = I: the estimate is exact and its variance 0 (up to
    // rounding: the variance must be computed from the deviations y_i - mean, Eq. 1.3).
    struct Case {
        std::string what;
        ps::Function1D f, sample, pdf;
        double value;
    };
    const Case cases[] = {
        {"sin(x) over [0, pi] with pdf sin(x) / 2 (x = acos(1 - 2u))", kSine.f,
         [](double u) { return std::acos(1.0 - 2.0 * u); },
         [](double x) { return x >= 0.0 && x <= kPiD ? 0.5 * std::sin(x) : 0.0; }, 2.0},
        {"x^2 over [0, 1] with pdf 3 x^2 (x = cbrt(u))", kSquare.f, [](double u) { return std::cbrt(u); },
         [](double x) { return x >= 0.0 && x <= 1.0 ? 3.0 * x * x : 0.0; }, 1.0 / 3.0},
    };
    for (const Case& c : cases) {
        ps::Rng rng(ps::testseed::seed(501));
        const Estimate e = ps::estimateImportance(c.f, c.sample, c.pdf, 1000, rng);
        CHECK_MESSAGE(std::abs(e.value - c.value) <= 1e-12 * c.value,
                      c.what << ": expected the exact value " << c.value << ", got " << e.value);
        CHECK_MESSAGE((e.variance >= 0.0 && e.variance <= 1e-24 * c.value * c.value),
                      c.what << ": expected variance 0 (<= 1e-24 I^2), got " << e.variance);
    }
}
