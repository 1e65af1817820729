// Lesson 1, graded: low-discrepancy points (lessons/01-monte-carlo/lowdiscrepancy.h; Eq. 1.15-1.20
// of the lesson README, section 1.8). The oracles are independent of the code under test: radical
// inverses worked out digit by digit (and, for base 2, by reversing the 64 bits of the index);
// the exact star discrepancy of a 1D point set from its closed form (Eq. 1.18) against the bound
// that the digit blocks of the index prove; the elementary boxes that the Chinese remainder
// theorem fills exactly once; and the variance of plain Monte Carlo, known in closed form, for
// the rate at which randomised Halton's error falls.
#include <doctest/doctest.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>
#include "01-monte-carlo/lowdiscrepancy.h"
#include "lesson01.h"
#include "seed.h"

using namespace lesson01;
using ps::Estimate;

namespace {

// Phi_b(i) as the integer fraction r / b^m, r the index's m digits in reverse: exact for the
// small indices (b^m < 2^53) the hand-made tables use.
double radicalInverseByDigits(uint64_t i, unsigned b) {
    uint64_t r = 0, d = 1;
    for (; i > 0; i /= b, d *= b) r = r * b + i % b;
    return static_cast<double>(r) / static_cast<double>(d);
}

// Phi_2(i) for any 64-bit i: the bits reversed, read as a fraction of 2^64. The conversion to
// double rounds once, to nearest (so UINT64_MAX gives exactly 1: the closest double, not < 1).
double radicalInverseBase2ByBits(uint64_t i) {
    uint64_t r = 0;
    for (int k = 0; k < 64; ++k, i >>= 1) r = (r << 1) | (i & 1u);
    return static_cast<double>(r) * 0x1p-64;
}

// Phi_b(i) for any 64-bit i: digits found by integer division, summed from the smallest term up
// in long double (error well below 1e-15 for the values checked here).
double radicalInverseLongDouble(uint64_t i, unsigned b) {
    std::vector<unsigned> digits;
    for (; i > 0; i /= b) digits.push_back(static_cast<unsigned>(i % b));
    long double v = 0.0L;
    for (size_t k = digits.size(); k-- > 0;) v = (v + digits[k]) / b;
    return static_cast<double>(v);
}

// The digits of i read in their original order behind the radix point, i / b^m: what a radical
// inverse that forgets to mirror returns (named in the failure message).
double unmirrored(uint64_t i, unsigned b) {
    double scale = 1.0;
    for (uint64_t m = i; m > 0; m /= b) scale *= b;
    return static_cast<double>(i) / scale;
}

std::string hex(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", x);
    return buf;
}

// The exact star discrepancy of points in [0, 1) (Eq. 1.18): sorted, D* = 1/(2N) +
// max_i |x_(i) - (2i - 1)/(2N)| (Niederreiter 1992, Theorem 2.6).
double starDiscrepancy1D(std::vector<double> x) {
    std::sort(x.begin(), x.end());
    const double N = static_cast<double>(x.size());
    double worst = 0.0;
    for (size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(x[i] - (2.0 * i + 1.0) / (2.0 * N)));
    return 1.0 / (2.0 * N) + worst;
}

// f = x e^(xy) over the unit square: I = e - 2; E[f^2] = integral of x (e^(2x) - 1) / 2 over
// [0, 1] = (e^2 - 1) / 8, so plain Monte Carlo's per-sample variance is (e^2 - 1)/8 - (e - 2)^2.
constexpr double kE = 2.71828182845904523536;
const ps::Function2D kSmooth = [](double x, double y) { return x * std::exp(x * y); };
constexpr double kSmoothValue = kE - 2.0;
constexpr double kSmoothVariance = (kE * kE - 1.0) / 8.0 - (kE - 2.0) * (kE - 2.0);

// The distance of two points of [0, 1) on the circle (a rotation may move a point across 0).
double circle(double a, double b) {
    const double d = std::abs(a - b);
    return std::min(d, 1.0 - d);
}

}  // namespace

TEST_CASE("low discrepancy: radical inverse of small indices against digits reversed by hand (Eq. 1.15) [1 pt]") {
    struct Case {
        uint64_t index;
        unsigned base;
        double value;  // worked out by hand: the digits of the index, mirrored
    };
    const Case cases[] = {
        {0, 2, 0.0},         {1, 2, 0.5},
        {2, 2, 0.25},        {3, 2, 0.75},
        {4, 2, 0.125},       {5, 2, 0.625},
        {6, 2, 0.375},       {11, 2, 13.0 / 16.0},  // 1011 -> .1101
        {1, 3, 1.0 / 3.0},   {2, 3, 2.0 / 3.0},
        {3, 3, 1.0 / 9.0},   {5, 3, 7.0 / 9.0},                                   // 12 -> .21
        {7, 5, 11.0 / 25.0}, {50, 7, 50.0 / 343.0},                               // 12 -> .21, 101
        {1234, 10, 0.4321},  {65537, 65536, 1.0 / 65536.0 + 1.0 / 4294967296.0},  // base 2^16
    };
    for (const Case& c : cases) {
        const double got = ps::radicalInverse(c.index, c.base);
        CHECK_MESSAGE(std::abs(got - c.value) <= 1e-15,
                      "radicalInverse(" << c.index << ", base " << c.base << "): expected " << num(c.value, 17)
                                        << ", got " << num(got, 17)
                                        << (got == unmirrored(c.index, c.base) && got != c.value
                                                ? " (the digits in their original order, not mirrored)"
                                                : ""));
    }
    // A table of the first 200 indices in bases 2, 3, 5 and 7 against the exact integer fraction.
    int wrong = 0;
    std::string first;
    for (unsigned b : {2u, 3u, 5u, 7u})
        for (uint64_t i = 0; i < 200; ++i) {
            const double want = radicalInverseByDigits(i, b), got = ps::radicalInverse(i, b);
            if (!(std::abs(got - want) <= 1e-15) && wrong++ == 0)
                first = "index " + std::to_string(i) + " in base " + std::to_string(b) + ": expected " + num(want, 17) +
                        ", got " + num(got, 17);
        }
    CHECK_MESSAGE(wrong == 0, wrong << " of the 800 radical inverses of indices 0..199 in bases 2, 3, 5 and 7 are "
                                       "wrong; first: "
                                    << first);
}

TEST_CASE("low discrepancy: radical inverse of indices past 2^32 up to 2^64 - 1 (Eq. 1.15) [2 pts]") {
    // Base 2 against the index's 64 bits reversed; an index that only has bits above 2^32
    // comes out 0 when it passes through 32 bits.
    const uint64_t base2[] = {uint64_t(1) << 32,     (uint64_t(1) << 40) + 1, (uint64_t(1) << 63) + 12345,
                              0x9e3779b97f4a7c15ull, 0x00000001fffffffeull,   0xdeadbeefcafef00dull};
    for (uint64_t i : base2) {
        const double want = radicalInverseBase2ByBits(i), got = ps::radicalInverse(i, 2);
        CHECK_MESSAGE(std::abs(got - want) <= 1e-15 * std::max(want, 1e-10),
                      "radicalInverse(" << i << ", base 2): expected " << num(want, 17) << ", got " << num(got, 17)
                                        << (got == 0.0 ? " (the index lost its upper 32 bits?)" : ""));
    }
    // Other bases against digits found by integer division and summed in long double.
    struct Case {
        uint64_t index;
        unsigned base;
    };
    const Case others[] = {{10460353203ull, 3},  // 3^21 > 2^32: one digit 1, twenty-one 0s
                           {0x123456789abcdefull, 3},
                           {0xfedcba9876543210ull, 5},
                           {(uint64_t(1) << 48) + 5, 65536},
                           {12157665459056928801ull, 3}};  // 3^40
    for (const Case& c : others) {
        const double want = radicalInverseLongDouble(c.index, c.base), got = ps::radicalInverse(c.index, c.base);
        CHECK_MESSAGE(std::abs(got - want) <= 1e-14 * want, "radicalInverse(" << c.index << ", base " << c.base
                                                                              << "): expected " << num(want, 17)
                                                                              << ", got " << num(got, 17));
    }
    // The largest indices: the exact value lies within 1e-19 of 1, and the nearest double is 1.
    // The result must still be below 1 (the contract: a coordinate in [0, 1)) and be the largest
    // double below 1 or within a few of it.
    const Case top[] = {{std::numeric_limits<uint64_t>::max(), 2},
                        {std::numeric_limits<uint64_t>::max() - 1, 2},  // ...1110: .0111...1
                        {12157665459056928800ull, 3},                   // 3^40 - 1: forty digits 2
                        {std::numeric_limits<uint64_t>::max(), 3}};
    for (const Case& c : top) {
        const double want = radicalInverseLongDouble(c.index, c.base), got = ps::radicalInverse(c.index, c.base);
        CHECK_MESSAGE((got < 1.0 && std::abs(got - want) <= 1e-15),
                      "radicalInverse(" << c.index << ", base " << c.base
                                        << "): expected just below 1 (within 1e-15 of " << num(want, 17)
                                        << ", and < 1), got " << num(got, 17) << " = " << hex(got));
    }
}

TEST_CASE("low discrepancy: star discrepancy of van der Corput points against its bound (Eq. 1.18) [2 pts]") {
    // For every N up to 1024 and bases 2, 3, 5, 7: the exact star discrepancy of the points
    // Phi_b(0..N-1) by the closed form of Eq. 1.18, against the bound of the README's proof: the
    // indices 0..N-1 split into sum_j a_j <= (b - 1)(floor(log_b N) + 1) blocks of b^j consecutive
    // indices, each a shifted lattice of spacing b^-j off by at most one point in any [0, x).
    // At N = b^k the points are the lattice k / N itself: D* = 1 / N exactly. Base 2 also meets
    // Bejian and Faure's sharper N D* <= log(N) / (3 log 2) + 1 (1977).
    for (unsigned b : {2u, 3u, 5u, 7u}) {
        std::vector<double> x;
        int reported = 0;
        uint64_t lattice = 1;
        for (uint64_t N = 1; N <= 1024; ++N) {
            x.push_back(ps::radicalInverse(N - 1, b));
            const double D = starDiscrepancy1D(x);
            int digits = 0, digitSum = 0;
            for (uint64_t m = N; m > 0; m /= b, ++digits) digitSum += static_cast<int>(m % b);
            const double bound = static_cast<double>(digitSum) / N + 1e-12;
            double sharper = bound;
            if (b == 2) sharper = std::min(bound, (std::log(double(N)) / (3.0 * std::log(2.0)) + 1.0) / N + 1e-12);
            bool ok = std::isfinite(D) && D <= sharper;
            std::string why = "above its bound " + num(sharper, 6);
            if (N == lattice) {
                ok = ok && std::abs(D - 1.0 / N) <= 1e-12;
                why = "at N = b^k the points are the lattice i / N, D* = 1 / N = " + num(1.0 / N, 6);
                lattice *= b;
            }
            if (!ok && reported++ < 3)
                CHECK_MESSAGE(false, "van der Corput points Phi_" << b << "(0.." << N - 1 << "): star discrepancy "
                                                                  << num(D, 6) << ", " << why);
        }
        CHECK_MESSAGE(reported == 0, "base " << b << ": " << reported
                                             << " of the point sets N = 1..1024 miss their discrepancy bound");
    }
}

TEST_CASE(
    "low discrepancy: the first 2^j 3^k Halton points, box by box, and the bases of dimensions 2-7 (Eq. 1.19) [2 pts]") {
    // Phi_b(i) lies in [a / b^k, (a + 1) / b^k) exactly when i mod b^k is a's k digits
    // reversed, so by the Chinese remainder theorem any 2^j 3^k consecutive indices put exactly
    // one point (Phi_2(i), Phi_3(i)) in each of the 2^j x 3^k boxes of that size (Eq. 1.19).
    struct Case {
        int j, k;
        uint64_t first;
    };
    const Case cases[] = {{3, 2, 0}, {5, 3, 0}, {2, 4, 0}, {4, 3, 1000}, {1, 1, 77}};
    for (const Case& c : cases) {
        const int nx = 1 << c.j, ny = static_cast<int>(std::lround(std::pow(3.0, c.k)));
        std::vector<int> count(static_cast<size_t>(nx) * ny, 0);
        int outside = 0;
        for (uint64_t i = c.first; i < c.first + static_cast<uint64_t>(nx) * ny; ++i) {
            const double x = ps::halton(i, 0), y = ps::halton(i, 1);
            if (!(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0)) {
                ++outside;
                continue;
            }
            // A point on a box's lower edge (k / 3^k in double) must not fall into the box below.
            const int bx = std::min(nx - 1, static_cast<int>(std::floor(x * nx + 1e-9)));
            const int by = std::min(ny - 1, static_cast<int>(std::floor(y * ny + 1e-9)));
            ++count[static_cast<size_t>(by) * nx + bx];
        }
        const int empty = static_cast<int>(std::count(count.begin(), count.end(), 0));
        CHECK_MESSAGE((outside == 0 && empty == 0),
                      "Halton points " << c.first << ".." << c.first + nx * ny - 1 << " in " << nx << " x " << ny
                                       << " boxes: " << empty << " boxes empty, " << outside
                                       << " points outside [0, 1)^2 (expected one point in every box)");
    }
    CHECK_MESSAGE((ps::halton(0, 0) == 0.0 && ps::halton(0, 1) == 0.0), "Halton point 0 is the origin");
    // Every dimension has its own prime: index 1 gives 1/p, index p + 1 (digits 1, 1) 1/p + 1/p^2.
    const unsigned primes[] = {2, 3, 5, 7, 11, 13, 17, 19};
    for (int d = 0; d < 8; ++d) {
        const double p = primes[d];
        const double got1 = ps::halton(1, d), got2 = ps::halton(primes[d] + 1, d);
        CHECK_MESSAGE((std::abs(got1 - 1.0 / p) <= 1e-15 && std::abs(got2 - (1.0 / p + 1.0 / (p * p))) <= 1e-15),
                      "Halton dimension " << d << " (base " << primes[d] << "): points 1 and " << primes[d] + 1
                                          << " expected " << num(1.0 / p, 12) << " and "
                                          << num(1.0 / p + 1.0 / (p * p), 12) << ", got " << num(got1, 12) << " and "
                                          << num(got2, 12));
    }
}

TEST_CASE("low discrepancy: Cranley-Patterson rotation of one coordinate (Eq. 1.20) [1 pt]") {
    struct Case {
        double x, shift, value;
    };
    const double below1 = std::nextafter(1.0, 0.0), belowHalf = std::nextafter(0.5, 0.0);
    const Case cases[] = {
        {0.25, 0.5, 0.75},
        {0.75, 0.5, 0.25},
        {0.0, 0.0, 0.0},
        {0.3, 0.0, 0.3},
        {below1, below1, 1.0 - 0x1p-52},  // 2 - 2^-52 wraps to 1 - 2^-52
        {0.5, belowHalf, 0.0},            // 1 - 2^-54 rounds to 1: wraps to 0
        {0.1, 0.95, 0.05},
    };
    for (const Case& c : cases) {
        const double got = ps::cranleyPatterson(c.x, c.shift);
        CHECK_MESSAGE((got >= 0.0 && got < 1.0 && circle(got, c.value) <= 1e-15),
                      "cranleyPatterson(" << num(c.x, 17) << ", shift " << num(c.shift, 17) << "): expected "
                                          << num(c.value, 17) << " (in [0, 1)), got " << num(got, 17) << " = "
                                          << hex(got));
    }
}

TEST_CASE(
    "low discrepancy: randomised Halton evaluates f at rotated Halton points 0..n-1, one shift per replicate (Eq. 1.20) [2 pts]") {
    // Records every point f is called at. Point 0 of the Halton sequence is the origin, so a
    // replicate with shift s calls f at s itself: every recorded point is a candidate shift, and
    // a candidate is a replicate's shift if all n rotated points are among the calls.
    const int n = 100, R = 3;
    std::vector<std::array<double, 2>> calls;
    const ps::Function2D f = [&](double x, double y) {
        calls.push_back({x, y});
        return x + 3.0 * y * y;
    };
    ps::Rng rng(ps::testseed::seed(601));
    const Estimate e = ps::estimateHalton2D(f, n, R, rng);
    REQUIRE_MESSAGE(calls.size() == size_t(n) * R, "expected " << n * R << " calls of f (" << n << " points x " << R
                                                               << " replicates), got " << calls.size());
    std::vector<std::array<double, 2>> halton(n);
    for (int i = 0; i < n; ++i) halton[i] = {radicalInverseByDigits(i, 2), radicalInverseByDigits(i, 3)};
    auto recorded = [&](double x, double y) {
        for (const auto& c : calls)
            if (circle(c[0], x) <= 1e-12 && circle(c[1], y) <= 1e-12) return true;
        return false;
    };
    std::vector<std::array<double, 2>> shifts;
    for (const auto& s : calls) {
        bool known = false;
        for (const auto& t : shifts) known = known || (circle(s[0], t[0]) <= 1e-12 && circle(s[1], t[1]) <= 1e-12);
        if (known) continue;
        bool all = true;
        for (int i = 0; i < n && all; ++i) {
            double x = halton[i][0] + s[0], y = halton[i][1] + s[1];
            all = recorded(x >= 1.0 ? x - 1.0 : x, y >= 1.0 ? y - 1.0 : y);
        }
        if (all) shifts.push_back(s);
    }
    CHECK_MESSAGE(shifts.size() == size_t(R),
                  "expected " << R << " replicates, each the Halton points 0.." << n - 1
                              << " (bases 2 and 3) rotated by its own shift; found " << shifts.size()
                              << " distinct shifts whose rotated point set f was called at");
    // The value: the mean of the replicates' averages; its variance: s^2 / R over those averages.
    std::vector<double> average(shifts.size(), 0.0);
    for (size_t r = 0; r < shifts.size(); ++r) {
        for (int i = 0; i < n; ++i) {
            double x = halton[i][0] + shifts[r][0], y = halton[i][1] + shifts[r][1];
            x = x >= 1.0 ? x - 1.0 : x;
            y = y >= 1.0 ? y - 1.0 : y;
            average[r] += (x + 3.0 * y * y) / n;
        }
    }
    if (shifts.size() == size_t(R)) {
        double mean = 0.0, squares = 0.0;
        for (double a : average) mean += a / R;
        for (double a : average) squares += (a - mean) * (a - mean);
        const double variance = squares / (R - 1.0) / R;
        CHECK_MESSAGE(std::abs(e.value - mean) <= 1e-12, "value: expected the mean of the replicates' averages "
                                                             << num(mean, 15) << ", got " << num(e.value, 15));
        CHECK_MESSAGE(std::abs(e.variance - variance) <= 1e-9 * variance,
                      "variance: expected " << num(variance, 10)
                                            << " from the spread of the replicates' averages (Eq. 1.3), got "
                                            << num(e.variance, 10));
    }
}

TEST_CASE("low discrepancy: randomised Halton is unbiased (t-test) and reports its variance [1 pt]") {
    ps::stats::Welford w;
    for (int r = 0; r < 100; ++r) {
        ps::Rng rng(ps::testseed::seed(602), uint64_t(r));
        w.add(ps::estimateHalton2D(kSmooth, 64, 4, rng).value);
    }
    const ps::stats::TTestResult t = ps::stats::tTest(w, kSmoothValue, alpha(), 0.005);
    CHECK_MESSAGE(t.passed,
                  "randomised Halton, x e^(xy) over [0, 1]^2, 64 points x 4 replicates (100 independent "
                  "runs): expected "
                      << kSmoothValue << ", got " << t.mean << " +- " << t.stdError << ". " << t.report);
    // The mean reported variance against the variance of 4000 independent estimates: +- 12 % is
    // more than 5 standard deviations of the latter (relative sd sqrt(2 / 3999) ~ 2.2 % for
    // near-normal values; measured 1.2 % to 2.5 % over seeds, as for the estimators' test).
    ps::stats::Welford values;
    double reported = 0.0;
    for (int r = 0; r < 4000; ++r) {
        ps::Rng rng(ps::testseed::seed(603), uint64_t(r));
        const Estimate e = ps::estimateHalton2D(kSmooth, 64, 4, rng);
        values.add(e.value);
        reported += e.variance / 4000.0;
    }
    const double ratio = reported / values.variance();
    CHECK_MESSAGE((values.variance() > 0.0 && std::isfinite(ratio) && std::abs(ratio - 1.0) < 0.12),
                  "randomised Halton, 64 points x 4 replicates: the variance of 4000 independent estimates is "
                      << values.variance() << ", the estimator reports " << reported << " on average (ratio " << ratio
                      << ", expected 1 +- 0.12)");
}

TEST_CASE("low discrepancy: randomised Halton's error against random sampling's as n grows (Eq. 1.17) [2 pts]") {
    // The root-mean-square error of estimateHalton2D over K = 400 runs at n = 36, 216 and 1296
    // points (6^k: whole boxes of Eq. 1.19), 2 replicates each, against plain Monte Carlo with the
    // same 2n points, whose error is known in closed form: sqrt(kSmoothVariance / 2n), slope -1/2
    // in log-log. By Eq. 1.17 Halton's error falls nearly as 1/n. Measured over 13 seeds: slope
    // -0.84 to -0.91 (sd 0.02), Halton 12.4 to 13.8 times below random at n = 1296 (sd 3 %).
    // Randomness enters only through the shifts; the bounds (slope below -0.7, at least 6 times
    // below random) sit more than 7 standard deviations from every measured value, so a correct
    // estimator fails by bad luck with a probability far below the lesson's alpha (not counted among
    // its statistical tests). A correlated or unreversed sequence stalls near the random rate.
    const int K = 400;
    const int ns[] = {36, 216, 1296};
    double rmse[3], random[3];
    for (int m = 0; m < 3; ++m) {
        double squares = 0.0;
        for (int r = 0; r < K; ++r) {
            ps::Rng rng(ps::testseed::seed(604 + m), uint64_t(r));
            const double err = ps::estimateHalton2D(kSmooth, ns[m], 2, rng).value - kSmoothValue;
            squares += err * err;
        }
        rmse[m] = std::sqrt(squares / K);
        random[m] = std::sqrt(kSmoothVariance / (2.0 * ns[m]));
    }
    const double slope = std::log(rmse[2] / rmse[0]) / std::log(1296.0 / 36.0);
    std::ostringstream table;
    for (int m = 0; m < 3; ++m)
        table << "\n  n = " << ns[m] << ": rms error " << num(rmse[m], 4) << ", random sampling's "
              << num(random[m], 4);
    CHECK_MESSAGE((std::isfinite(slope) && slope < -0.7 && rmse[2] * 6.0 < random[2]),
                  "randomised Halton on x e^(xy), 2 replicates, " << K << " runs each: log-log slope of the error "
                                                                  << num(slope, 3)
                                                                  << " (random sampling: -0.5; expected below -0.7), "
                                                                     "and at n = 1296 at least 6 times below random:"
                                                                  << table.str());
}
