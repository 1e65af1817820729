// Statistical tests for graded and framework tests (recipes: ../shared/notes/testing.md).
// Every test takes its significance level alpha explicitly; callers that run m tests in one
// suite pass sidak(0.01, m). Every result carries a report that says what was expected and
// what was got, for failure messages.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>
#include "image.h"
#include "vecmath.h"

namespace ps::stats {

// Per-test level that keeps the family-wise level alpha over m independent tests:
// 1 - (1 - alpha)^(1/m).
double sidak(double alpha, int m);

// Upper tail of the chi-square distribution with dof degrees of freedom: P(X >= x).
double chiSquareSurvival(double x, int dof);
// Two-sided p-value of Student's t with dof degrees of freedom: P(|T| >= |t|).
double studentTwoSided(double t, double dof);
// Two-sided p-value of the standard normal: P(|Z| >= |z|).
double normalTwoSided(double z);

struct ChiSquareResult {
    bool passed = false;
    double statistic = 0.0, pValue = 0.0;
    int dof = 0;
    std::string report;  // statistic, dof, p, alpha; on failure the worst cells
};

// Pearson's test of observed counts against expected counts (same length, expected summing to
// the sample count). Cells are sorted by expected count and those with expected < minExpected
// pooled; a cell with expected 0 that holds more than 1e-5 * N samples fails at once.
ChiSquareResult chiSquare(const std::vector<double>& observed, const std::vector<double>& expected, double alpha,
                          double minExpected = 5.0);

// Goodness of fit of a direction sampler against its pdf (per unit solid angle) over the
// sphere, in the equal-area parametrisation (cos(theta), phi): thetaBins x phiBins cells,
// expected counts by integrating the pdf over each cell (a 4x4 Gauss rule per cell, or finer).
// sample(u) may return a zero vector for an invalid sample (it then counts in no cell).
// On failure, writes observed and expected tables to dumpPath (if not empty).
ChiSquareResult chiSquareSphere(const std::function<Vec3(const Vec2&)>& sample,
                                const std::function<double(const Vec3&)>& pdf, int thetaBins, int phiBins, int samples,
                                uint64_t seed, double alpha, const std::string& dumpPath = "");

// The same for a sampler of points in the rectangle [lo, hi] with pdf per unit area.
ChiSquareResult chiSquarePlanar(const std::function<Vec2(const Vec2&)>& sample,
                                const std::function<double(const Vec2&)>& pdf, const Vec2& lo, const Vec2& hi, int bins,
                                int samples, uint64_t seed, double alpha, const std::string& dumpPath = "");

// Running mean and variance (Welford), in double.
struct Welford {
    uint64_t n = 0;
    double mean = 0.0, m2 = 0.0;
    void add(double x);
    double variance() const;  // sample variance
    double stdError() const;  // sqrt(variance / n)
};

// Welford per pixel and channel over independent images of one size: their mean image and its
// variance of the mean (what writeFailedImages takes), for the images a failed test writes.
struct ImageWelford {
    int width = 0, height = 0;
    std::vector<Welford> channels;  // pixel-major, three per pixel
    void add(const Image& img);     // the first image sets the size; later ones must match it
    Image mean() const;
    Image varianceOfMean() const;
};

struct TTestResult {
    bool passed = false;
    double mean = 0.0, reference = 0.0, stdError = 0.0, t = 0.0, pValue = 0.0;
    std::string report;
};

// Two-sided t-test of H0: E[X] = reference. With maxRelStdError > 0 it also fails when the
// standard error exceeds maxRelStdError * |reference| (power check: a noisy estimator must
// not pass for lack of evidence).
TTestResult tTest(const Welford& samples, double reference, double alpha, double maxRelStdError);

struct ZTestResult {
    bool passed = false;
    double fractionPassed = 0.0;  // of pixel channels
    int failed = 0, total = 0;
    std::string report;  // the worst pixels: position, channel, values, z
};

// Per-pixel z-test of two independent estimates a and b of the same image, each with its
// variance of the mean (Film::varianceOfMean): z = |a - b| / sqrt(varA + varB + floor).
// Each pixel channel is tested at level sidak(alpha, pixels * 3); the images agree when at
// least requiredFraction of the channels pass.
// A failed test also writes the four images (writeFailedImages) and its report ends with the
// `pathspace compare` command that shows where a and b differ.
ZTestResult zTestImages(const Image& a, const Image& varA, const Image& b, const Image& varB, double alpha,
                        double requiredFraction = 0.9975, double varianceFloor = 1e-8);

// Writes a, b and their variances as PFM files a.pfm, a-variance.pfm, b.pfm, b-variance.pfm in
// build/failed-images/NAME/ (NAME from the running test's name; the working folder's
// failed-images/NAME/ when the build tree cannot be written; an empty variance image is left out)
// and returns the line that names the `pathspace compare` command to run on them (or why they
// could not be written). In a CHECK_MESSAGE it runs only when the check fails.
std::string writeFailedImages(const Image& a, const Image& varA, const Image& b, const Image& varB);
// The running test's name, for those file names: set by the test programs' main (doctest_main.cpp).
void setCurrentTestName(const std::string& name);

// Integral of f over the unit sphere (per unit solid angle) or over the rectangle [lo, hi] (per unit
// area), by the adaptive Gauss-Legendre cubature the chi-square tests use for their expected
// counts; NaN if f is NaN, Inf or negative anywhere it is evaluated. For "pdf integrates to 1"
// checks; accuracy documented in statistics.cpp (peaked lobes to ~1e-9).
double integrateSphere(const std::function<double(const Vec3&)>& f);
double integratePlanar(const std::function<double(const Vec2&)>& f, const Vec2& lo, const Vec2& hi);

}  // namespace ps::stats
