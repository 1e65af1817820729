// Lesson 1, graded: the estimators' bookkeeping checked exactly, without statistics. The
// statistical tests (test_estimators.cpp) cannot see a mistake of 1/n in a variance or a
// forgotten stratum of width 1/1000; these can: a stratified estimator must put exactly one
// sample in each stratum, and with sample values the test chooses, the value and the variance
// an estimator reports are known exactly (Eq. 1.3, 1.4). Found missing by scripts/mutants.sh.
#include <doctest/doctest.h>
#include <cmath>
#include <vector>
#include "01-monte-carlo/estimators.h"
#include "lesson01.h"
#include "seed.h"

namespace {

bool near(double got, double expected) { return std::abs(got - expected) <= 1e-9 * std::abs(expected); }

}  // namespace

TEST_CASE("estimators: the sample mean reports the variance s^2 / n with the unbiased s^2 (Eq. 1.3) [1 pt]") {
    // Importance sampling with a "sampler" that ignores u and yields 1, 2, 3, 4 (pdf 1, f(x) = x):
    // the samples are exactly 1, 2, 3, 4, mean 2.5, s^2 = 5/3, variance of the mean 5/12.
    int next = 0;
    const ps::Function1D sample = [&](double) { return double(1 + next++ % 4); };
    const ps::Function1D pdf = [](double) { return 1.0; };
    const ps::Function1D f = [](double x) { return x; };
    ps::Rng rng(ps::testseed::seed(601));
    const ps::Estimate e = ps::estimateImportance(f, sample, pdf, 4, rng);
    CHECK_MESSAGE(near(e.value, 2.5), "samples 1, 2, 3, 4: expected the mean 2.5, got " << e.value);
    const double ratio = e.variance / (5.0 / 12.0);
    CHECK_MESSAGE(near(e.variance, 5.0 / 12.0),
                  "samples 1, 2, 3, 4: expected the variance of the mean s^2 / n = (5/3) / 4 = 0.41667, got "
                      << e.variance << " (ratio " << ratio << "; 0.75: divided by n instead of n - 1? 4: "
                      << "the variance of the samples, not of their mean (1/n missing)?)");
    // A sample where the pdf is 0 (a sampler that can fail, as a BSDF's can) counts as 0 (Eq. 1.5):
    // the samples 1, 2, 3, 4 with pdf 0 at 3 give 1, 2, 0, 4: mean 7/4, s^2 = 35/12, variance 35/48.
    next = 0;
    const ps::Function1D pdfHole = [](double x) { return x == 3.0 ? 0.0 : 1.0; };
    const ps::Estimate h = ps::estimateImportance(f, sample, pdfHole, 4, rng);
    CHECK_MESSAGE((near(h.value, 1.75) && near(h.variance, 35.0 / 48.0)),
                  "samples 1, 2, 3, 4 with pdf 0 at x = 3: expected that sample to count 0, the mean 1.75 and "
                  "the variance 0.72917, got "
                      << h.value << " and " << h.variance << " (f / pdf with pdf = 0 is Inf or NaN, not 0)");
}

TEST_CASE(
    "estimators: stratified sampling puts exactly one sample in each stratum, and reports Eq. 1.4's variance [2 pts]") {
    // 1D: [0, 5] in 5 strata of width 1; f is 0, 1, 0, 2, 0 on the strata (constant on each),
    // and records where it was called. Value = sum h f = 3; second differences -2, 3, -4, so the
    // variance is N / (6 M) sum d^2 = 5 / 18 * 29.
    {
        const double table[5] = {0.0, 1.0, 0.0, 2.0, 0.0};
        std::vector<int> hits(5, 0);
        int outside = 0;
        const ps::Function1D f = [&](double x) {
            const int k = int(std::floor(x));
            if (k < 0 || k > 4) {
                ++outside;
                return 0.0;
            }
            ++hits[k];
            return table[k];
        };
        ps::Rng rng(ps::testseed::seed(602));
        const ps::Estimate e = ps::estimateStratified(f, 0.0, 5.0, 5, rng);
        bool once = outside == 0;
        for (int k = 0; k < 5; ++k) once = once && hits[k] == 1;
        CHECK_MESSAGE(once, "5 strata of [0, 5]: expected exactly one sample in each stratum, got the counts "
                                << hits[0] << ", " << hits[1] << ", " << hits[2] << ", " << hits[3] << ", " << hits[4]
                                << " and " << outside << " outside (a stratum left out or the width off by one?)");
        CHECK_MESSAGE(near(e.value, 3.0), "stratified 1D: expected the value 3 (sum of h F_k), got " << e.value);
        CHECK_MESSAGE(near(e.variance, 5.0 / 18.0 * 29.0),
                      "stratified 1D, F = 0, 1, 0, 2, 0: expected N / (6 M) sum d_k^2 = 5 / 18 * 29 = 8.0556, got "
                          << e.variance << " (ratio " << e.variance / (5.0 / 18.0 * 29.0) << ")");
    }
    // 2D: 3 x 3 cells of side h = 1/3; f is, row by row (j = 0, 1, 2 along y, i along x),
    // 0 1 0 / 5 5 5 / 0 0 0. Value = h^2 * 16; in-row second differences -2 h^2, 0, 0 (never
    // across the end of a row), so the variance is 9 / 18 * 4 h^4 = 2 / 81.
    {
        const double table[3][3] = {{0.0, 1.0, 0.0}, {5.0, 5.0, 5.0}, {0.0, 0.0, 0.0}};
        std::vector<int> hits(9, 0);
        int outside = 0;
        const ps::Function2D f = [&](double x, double y) {
            const int i = int(std::floor(3.0 * x)), j = int(std::floor(3.0 * y));
            if (i < 0 || i > 2 || j < 0 || j > 2) {
                ++outside;
                return 0.0;
            }
            ++hits[3 * j + i];
            return table[j][i];
        };
        ps::Rng rng(ps::testseed::seed(603));
        const ps::Estimate e = ps::estimateStratified2D(f, 3, rng);
        bool once = outside == 0;
        for (int c = 0; c < 9; ++c) once = once && hits[c] == 1;
        CHECK_MESSAGE(once, "3 x 3 cells: expected exactly one sample in each cell (" << outside << " outside)");
        CHECK_MESSAGE(near(e.value, 16.0 / 9.0), "stratified 2D: expected the value 16 h^2 = 1.7778, got "
                                                     << e.value << " (ratio " << e.value / (16.0 / 9.0)
                                                     << "; 3: h instead of h^2?)");
        CHECK_MESSAGE(near(e.variance, 2.0 / 81.0),
                      "stratified 2D, rows 0 1 0 / 5 5 5 / 0 0 0: expected 9 / (6 * 3) * 4 h^4 = 0.024691, got "
                          << e.variance << " (ratio " << e.variance / (2.0 / 81.0)
                          << "; second differences across the end of a row, or N missing?)");
    }
}
