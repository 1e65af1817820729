// Statistical tests for graded and framework tests (recipes: ../shared/notes/testing.md).
//
//   1. special functions: chi-square, Student t and normal tail probabilities
//   2. Pearson's chi-square with pooled low cells (pbrt-v3 / Mitsuba / Nori recipe)
//   3. adaptive Gauss-Legendre cubature for the expected counts
//   4. chi-square of a sampler over the sphere and over a rectangle
//   5. Welford, t-test on a scalar mean, per-pixel z-test of two images (a failed one writes them)
#include "statistics.h"
#include <cctype>
#include <filesystem>
#include <map>
#include "lesson_files.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <limits>
#include <numeric>
#include <stdexcept>
#include "rng.h"

namespace ps::stats {

namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kInfD = std::numeric_limits<double>::infinity();

// printf into a std::string (reports are built from numbers).
std::string format(const char* fmt, ...) {
    char buf[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, args);
    va_end(args);
    return buf;
}

// ---------------------------------------------------------------------------------------------
// 1. Special functions (Numerical Recipes, 3rd ed., sections 6.2 and 6.4), in double.

constexpr int kMaxIterations = 1000000;  // the series and fractions need O(sqrt(a)) terms
constexpr double kEps = 1e-15;
constexpr double kTiny = 1e-300;  // guards the modified Lentz recurrences

// Regularized lower incomplete gamma P(a, x) by its series, for x < a + 1:
// P(a, x) = e^{-x} x^a / Gamma(a) * sum_n x^n / (a (a+1) ... (a+n)).
double gammaSeriesP(double a, double x) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < kMaxIterations; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * kEps) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Regularized upper incomplete gamma Q(a, x) by its continued fraction (modified Lentz), for
// x >= a + 1: Q(a, x) = e^{-x} x^a / Gamma(a) * 1/(x+1-a- 1(1-a)/(x+3-a- 2(2-a)/(x+5-a- ...))).
double gammaFractionQ(double a, double x) {
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i < kMaxIterations; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < kEps) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

// Q(a, x) = Gamma(a, x) / Gamma(a).
double gammaQ(double a, double x) {
    if (!(a > 0.0) || !(x >= 0.0)) return std::numeric_limits<double>::quiet_NaN();
    if (x == 0.0) return 1.0;
    if (x == kInfD) return 0.0;
    return x < a + 1.0 ? 1.0 - gammaSeriesP(a, x) : gammaFractionQ(a, x);
}

// Continued fraction of the incomplete beta function (NR betacf, modified Lentz):
// I_x(a, b) = x^a (1-x)^b / (a B(a, b)) * 1/(1+ d1/(1+ d2/(1+ ...))), with
// d_{2m+1} = -(a+m)(a+b+m) x / ((a+2m)(a+2m+1)), d_{2m} = m(b-m) x / ((a+2m-1)(a+2m)).
double betaFraction(double a, double b, double x) {
    double qab = a + b, qap = a + 1.0, qam = a - 1.0;
    double c = 1.0, d = 1.0 - qab * x / qap;
    if (std::abs(d) < kTiny) d = kTiny;
    d = 1.0 / d;
    double h = d;
    for (int m = 1; m < kMaxIterations; ++m) {
        int m2 = 2 * m;
        double aa = m * (b - m) * x / ((qam + m2) * (a + m2));  // even step
        d = 1.0 + aa * d;
        if (std::abs(d) < kTiny) d = kTiny;
        c = 1.0 + aa / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        h *= d * c;
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));  // odd step
        d = 1.0 + aa * d;
        if (std::abs(d) < kTiny) d = kTiny;
        c = 1.0 + aa / c;
        if (std::abs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < kEps) break;
    }
    return h;
}

// Regularized incomplete beta I_x(a, b), given x and y = 1 - x separately (y is often tiny and
// must not be computed as 1 - x). Uses the symmetry I_x(a, b) = 1 - I_y(b, a) where the
// fraction converges fast.
double betaI(double a, double b, double x, double y) {
    if (x <= 0.0) return 0.0;
    if (y <= 0.0) return 1.0;
    double logX = x < 0.5 ? std::log(x) : std::log1p(-y);
    double logY = y < 0.5 ? std::log(y) : std::log1p(-x);
    // x^a y^b / B(a, b), B(a, b) = Gamma(a) Gamma(b) / Gamma(a + b)
    double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * logX + b * logY);
    if (x < (a + 1.0) / (a + b + 2.0)) return front * betaFraction(a, b, x) / a;
    return 1.0 - front * betaFraction(b, a, y) / b;
}

// ---------------------------------------------------------------------------------------------
// 2. Pearson's chi-square with pooling.

using CellName = std::function<std::string(size_t)>;

struct Term {
    std::string name;
    double observed, expected;
    bool noCell = false;  // the samples that fell in no cell (invalid or outside the domain)
    double contribution() const { return (observed - expected) * (observed - expected) / expected; }
};

ChiSquareResult rejectWith(std::string report) {
    ChiSquareResult r;
    r.report = std::move(report);
    return r;
}

// Validates the tables; empty string when they are usable.
std::string checkTables(const std::vector<double>& observed, const std::vector<double>& expected, double alpha,
                        const CellName& name) {
    if (observed.size() != expected.size() || observed.empty())
        return format("chi-square: %zu observed and %zu expected cells (must be equal and non-zero): rejected",
                      observed.size(), expected.size());
    if (!(alpha > 0.0 && alpha < 1.0)) return format("chi-square: alpha %g not in (0, 1): rejected", alpha);
    for (size_t i = 0; i < observed.size(); ++i) {
        if (!(std::isfinite(observed[i]) && observed[i] >= 0.0))
            return "chi-square: " + name(i) + format(" has observed count %g: rejected", observed[i]);
        if (!(std::isfinite(expected[i]) && expected[i] >= 0.0))
            return "chi-square: " + name(i) + format(" has expected count %g: rejected", expected[i]);
    }
    return "";
}

// Pooling as in pbrt-v3 (chi2test): cells in order of increasing expected count; those with
// expected < minExpected, and then further ones until the pool reaches minExpected, go into a
// single pooled cell. Cells with expected 0 are left out (the zero rule has judged them).
std::vector<Term> poolCells(const std::vector<double>& observed, const std::vector<double>& expected,
                            double minExpected, const CellName& name, size_t noCell, int& pooledCells) {
    std::vector<size_t> order(expected.size());
    std::iota(order.begin(), order.end(), size_t(0));
    // By expected count, ties in index order (a total order: std::sort gives stable_sort's result).
    std::sort(order.begin(), order.end(),
              [&](size_t i, size_t j) { return expected[i] != expected[j] ? expected[i] < expected[j] : i < j; });
    std::vector<Term> terms;
    double pooledObserved = 0.0, pooledExpected = 0.0;
    pooledCells = 0;
    for (size_t i : order) {
        if (expected[i] == 0.0) continue;
        if (i == noCell && expected[i] >= minExpected) {
            terms.push_back({name(i), observed[i], expected[i], true});
            continue;
        }
        if (expected[i] < minExpected || (pooledExpected > 0.0 && pooledExpected < minExpected)) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            ++pooledCells;
        } else {
            terms.push_back({name(i), observed[i], expected[i]});
        }
    }
    if (pooledCells > 0)
        terms.push_back({format("pooled cell (%d cells)", pooledCells), pooledObserved, pooledExpected});
    return terms;
}

// The up to 5 cells of the domain that contribute most to the statistic, for failure reports.
// The samples in no cell are reported on their own line: when a pdf integrates to less than 1
// they dominate the statistic, and listing them first would hide where in the domain the
// sampler and the pdf disagree.
std::string worstCells(std::vector<Term> terms) {
    std::string s;
    const auto none = std::find_if(terms.begin(), terms.end(), [](const Term& t) { return t.noCell; });
    if (none != terms.end()) {
        s += format("\n  %s: observed %.0f expected %.1f (the pdf's missing mass)", none->name.c_str(), none->observed,
                    none->expected);
        terms.erase(none);
    }
    size_t k = std::min<size_t>(5, terms.size());
    std::partial_sort(terms.begin(), terms.begin() + k, terms.end(),
                      [](const Term& a, const Term& b) { return a.contribution() > b.contribution(); });
    s += "\n  worst cells:";
    for (size_t i = 0; i < k; ++i)
        s += format("%s %s observed %.0f expected %.1f", i ? ";" : "", terms[i].name.c_str(), terms[i].observed,
                    terms[i].expected);
    return s;
}

// A pdf whose integral over the domain is not 1: said first, since it explains the rest (a pdf
// off by a constant factor, e.g. a missing 1/pi or a factor 2, puts every cell off by it).
std::string integralReport(double integral, const char* domain) {
    if (std::abs(integral - 1.0) <= 1e-3) return "";
    return format("the pdf integrates to %.4f over %s, not 1 (off by a factor %.4g if it is a constant factor); ",
                  integral, domain, integral);
}

ChiSquareResult pearson(const std::vector<double>& observed, const std::vector<double>& expected, double alpha,
                        double minExpected, const CellName& name, size_t noCell = size_t(-1)) {
    std::string invalid = checkTables(observed, expected, alpha, name);
    if (!invalid.empty()) return rejectWith(invalid);

    // Zero rule: samples where the pdf is 0. A few are forgiven (rounding), as in pbrt.
    const double n = std::accumulate(observed.begin(), observed.end(), 0.0);
    for (size_t i = 0; i < observed.size(); ++i)
        if (expected[i] == 0.0 && observed[i] > 1e-5 * n)
            return rejectWith("chi-square: " + name(i) +
                              format(" has expected count 0 but received %.0f samples (> 1e-5 N = %.3g): "
                                     "rejected at any alpha",
                                     observed[i], 1e-5 * n));

    ChiSquareResult r;
    int pooledCells = 0;
    std::vector<Term> terms = poolCells(observed, expected, minExpected, name, noCell, pooledCells);
    for (const Term& t : terms) r.statistic += t.contribution();  // X^2 = sum (O - E)^2 / E
    r.dof = int(terms.size()) - 1;
    if (r.dof < 1)
        return rejectWith(
            format("chi-square: only %zu cell(s) after pooling (dof %d < 1): too few samples or "
                   "cells for a test: rejected",
                   terms.size(), r.dof));
    r.pValue = chiSquareSurvival(r.statistic, r.dof);
    r.passed = r.pValue >= alpha;
    r.report = format("chi-square: statistic %.1f, dof %d, p = %.3g %s alpha %.3g: %s (%zu cells, %d pooled)",
                      r.statistic, r.dof, r.pValue, r.passed ? ">=" : "<", alpha, r.passed ? "accepted" : "rejected",
                      observed.size(), pooledCells);
    if (!r.passed) r.report += worstCells(terms);
    return r;
}

// ---------------------------------------------------------------------------------------------
// 3. Adaptive cubature: a 4x4 Gauss-Legendre product rule (exact for bi-degree 7) on a box,
// compared with the same rule on its four quadrants; a box recurses while they disagree by more
// than max(absTol, 1e-6 |I|), up to kMaxDepth halvings. A box also recurses, to the full depth,
// while it straddles the edge of the pdf's support (some of its quadrant nodes and corners see
// 0, some do not) and the values seen there could matter (the largest value over 5 % of the box
// exceeds the tolerance): a jump to 0 in a thin sliver between the nodes would fool the error
// estimate (a disk pdf lost 2.4e-5 of its mass that way), and a straight support edge always
// leaves a corner on each side. The corners are probed 1e-3 of the box inside, so that a support
// edge lying on a box edge (the horizon) does not count as straddling. Jumps between two nonzero
// values are found by the error estimate only.
// Boxes start no larger than a base size (kSphereBase below), so a narrow peak is seen by some
// node before the error estimate is trusted. The tolerances sit above the noise of the integrand: pdfs take float vectors, whose
// rounding alone makes pdf values wobble by ~1e-7 relative (more for cos^n with large n), and a
// tighter tolerance would only refine noise to the maximum depth.

constexpr double kGaussX[4] = {-0.8611363115940525752, -0.3399810435848562648, 0.3399810435848562648,
                               0.8611363115940525752};
constexpr double kGaussW[4] = {0.3478548451374538574, 0.6521451548625461426, 0.6521451548625461426,
                               0.3478548451374538574};
constexpr int kMaxDepth = 5;
constexpr double kRelTol = 1e-6;

struct Box {
    double u0, u1, v0, v1;
};

// The 4x4 rule on box b; adds the number of nodes where f is 0 to zeros and keeps the largest
// value in maxValue.
template <class F>
double gauss4x4(const F& f, const Box& b, int& zeros, double& maxValue) {
    const double cu = 0.5 * (b.u0 + b.u1), hu = 0.5 * (b.u1 - b.u0);
    const double cv = 0.5 * (b.v0 + b.v1), hv = 0.5 * (b.v1 - b.v0);
    double sum = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const double v = f(cu + hu * kGaussX[i], cv + hv * kGaussX[j]);
            zeros += v == 0.0;
            maxValue = std::max(maxValue, v);
            sum += kGaussW[i] * kGaussW[j] * v;
        }
    return sum * hu * hv;
}

template <class F>
double gauss4x4(const F& f, const Box& b) {
    int zeros = 0;
    double maxValue = 0.0;
    return gauss4x4(f, b, zeros, maxValue);
}

// Probes the four corners of b, 1e-3 of the box inside: counts zeros, keeps the largest value.
template <class F>
void probeCorners(const F& f, const Box& b, int& zeros, double& maxValue) {
    const double du = 1e-3 * (b.u1 - b.u0), dv = 1e-3 * (b.v1 - b.v0);
    for (double u : {b.u0 + du, b.u1 - du})
        for (double v : {b.v0 + dv, b.v1 - dv}) {
            const double value = f(u, v);
            zeros += value == 0.0;
            maxValue = std::max(maxValue, value);
        }
}

template <class F>
double refine(const F& f, const Box& b, double whole, double absTol, int depth) {
    const double um = 0.5 * (b.u0 + b.u1), vm = 0.5 * (b.v0 + b.v1);
    const Box q[4] = {{b.u0, um, b.v0, vm}, {um, b.u1, b.v0, vm}, {b.u0, um, vm, b.v1}, {um, b.u1, vm, b.v1}};
    double part[4], sum = 0.0;
    int zeros = 0;
    double maxValue = 0.0;
    for (int k = 0; k < 4; ++k) sum += part[k] = gauss4x4(f, q[k], zeros, maxValue);
    probeCorners(f, b, zeros, maxValue);
    const bool straddlesSupport =
        zeros > 0 && zeros < 4 * 16 + 4 && 0.05 * maxValue * (b.u1 - b.u0) * (b.v1 - b.v0) > absTol;
    if (depth == 0 || (!straddlesSupport && std::abs(sum - whole) <= std::max(absTol, kRelTol * std::abs(sum))))
        return sum;
    double total = 0.0;
    for (int k = 0; k < 4; ++k) total += refine(f, q[k], part[k], 0.25 * absTol, depth - 1);
    return total;
}

// Integral of f(u, v) over box, split first into nu x nv base boxes; absTol per base box is
// tolDensity times its measure (measure(box) gives it).
template <class F, class M>
double integrateBox(const F& f, const Box& box, int nu, int nv, double tolDensity, const M& measure) {
    double total = 0.0;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            Box b{box.u0 + (box.u1 - box.u0) * i / nu, box.u0 + (box.u1 - box.u0) * (i + 1) / nu,
                  box.v0 + (box.v1 - box.v0) * j / nv, box.v0 + (box.v1 - box.v0) * (j + 1) / nv};
            total += refine(f, b, gauss4x4(f, b), tolDensity * measure(b), kMaxDepth);
        }
    return total;
}

// A pdf that records invalid values (NaN, Inf, negative) instead of letting them into the sums.
template <class P>
struct CheckedPdf {
    const std::function<double(const P&)>& pdf;
    mutable long invalid = 0;
    mutable double firstInvalid = 0.0;
    mutable P firstInvalidAt{};
    double operator()(const P& x) const {
        double p = pdf(x);
        if (std::isfinite(p) && p >= 0.0) return p;
        if (invalid++ == 0) firstInvalid = p, firstInvalidAt = x;
        return 0.0;
    }
};

// Sphere cells are integrated over (theta, phi) with d omega = sin(theta) d theta d phi, not over
// (cos theta, phi): a lobe around a pole of width 1/sqrt(n) in angle is only ~1/n wide in
// cos(theta). Base boxes are at most kSphereBase radians on a side (arc length); the horizon
// theta = pi/2 is always a box edge, so hemispherical pdfs have no jump inside a box.
// With 0.04 rad base boxes, every direction has a node of the quadrant rule within ~0.005 rad,
// so lobes of angular width sigma >= 0.002 rad (Phong exponents n = 1/sigma^2 up to ~3e5) are
// always seen, then refined.
// Accuracy of the integral over the whole sphere (integrateSphere on the 51 x 102 grid, measured):
//   uniform 1e-13, cosine 1e-9, Phong about a tilted axis: n = 20 1e-9, n = 1e4 2e-8,
//   n = 1e5 1.2e-7, n = 1e6 2.5e-6; uniform hemisphere about a tilted axis (a jump crossing
//   boxes) 2e-8. Cost: 0.035 s (uniform) to 0.12 s (Phong 1e4) on one core.
// For the chi-square an error delta in an expected count E adds ~delta^2 / E to the statistic:
// at N = 1e6 samples these errors are below 0.1 count per cell, i.e. negligible.
constexpr double kSphereBase = 0.04;
constexpr double kSphereTolDensity = 1e-9 / (4.0 * kPiD);  // absolute tolerance per steradian

Vec3 sphericalDirection(double theta, double phi) {
    double s = std::sin(theta);
    return Vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(std::cos(theta)));
}

template <class F>
double integrateSphereCell(const F& pdf, double z0, double z1, double phi0, double phi1) {
    auto integrand = [&](double theta, double phi) { return pdf(sphericalDirection(theta, phi)) * std::sin(theta); };
    auto solidAngle = [](const Box& b) { return (std::cos(b.u0) - std::cos(b.u1)) * (b.v1 - b.v0); };
    std::vector<double> cuts = {std::acos(z1)};  // theta grows as z falls
    if (z0 < 0.0 && z1 > 0.0) cuts.push_back(0.5 * kPiD);
    cuts.push_back(std::acos(z0));
    double total = 0.0;
    for (size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double ta = cuts[k], tb = cuts[k + 1];
        const double sinMax = (ta <= 0.5 * kPiD && tb >= 0.5 * kPiD) ? 1.0 : std::max(std::sin(ta), std::sin(tb));
        const int nTheta = std::max(1, int(std::ceil((tb - ta) / kSphereBase)));
        const int nPhi = std::max(1, int(std::ceil(sinMax * (phi1 - phi0) / kSphereBase)));
        total += integrateBox(integrand, Box{ta, tb, phi0, phi1}, nTheta, nPhi, kSphereTolDensity, solidAngle);
    }
    return total;
}

// Planar cells: base boxes at most 1/64 of the rectangle on a side. Accuracy (measured): the
// disk pdf 1/pi on [-1, 1]^2 (a curved support edge through the cells) 3e-7 over 51 x 51 cells.
constexpr int kPlanarBaseDivisions = 64;

template <class F>
double integratePlanarCell(const F& pdf, const Box& cell, const Vec2& lo, const Vec2& hi) {
    auto integrand = [&](double x, double y) { return pdf(Vec2(float(x), float(y))); };
    const double area = double(hi.x - lo.x) * double(hi.y - lo.y);
    auto measure = [](const Box& b) { return (b.u1 - b.u0) * (b.v1 - b.v0); };
    const int nu = std::max(1, int(std::ceil((cell.u1 - cell.u0) / (hi.x - lo.x) * kPlanarBaseDivisions)));
    const int nv = std::max(1, int(std::ceil((cell.v1 - cell.v0) / (hi.y - lo.y) * kPlanarBaseDivisions)));
    return integrateBox(integrand, cell, nu, nv, 1e-9 / area, measure);
}

// ---------------------------------------------------------------------------------------------
// 4. Chi-square of samplers. Both tables have rows x cols cells plus one last cell for the
// samples that land in no cell (invalid / outside): its expected count is N - sum(expected),
// so a sampler whose pdf integrates to less than 1 is tested on how often it fails, too.

struct Grid {
    int rows, cols;
    std::vector<double> observed, expected;  // rows * cols + 1 (the last: no cell)
    Grid(int r, int c) : rows(r), cols(c), observed(size_t(r) * c + 1, 0.0), expected(size_t(r) * c + 1, 0.0) {}
    size_t noCell() const { return size_t(rows) * cols; }
};

// Observed then expected table as two whitespace-separated matrices (numpy.loadtxt reads the
// file as a (2 rows) x cols array: the top half observed, the bottom half expected).
void dumpTables(const std::string& path, const std::string& header, const Grid& g, const ChiSquareResult& r) {
    if (path.empty()) return;
    std::ofstream out(path);
    if (!out) return;
    out << "# " << header << "\n";
    for (size_t start = 0; start < r.report.size();) {  // the report may span lines: comment each
        size_t end = std::min(r.report.find('\n', start), r.report.size());
        out << "# " << r.report.substr(start, end - start) << "\n";
        start = end + 1;
    }
    out << format("# samples in no cell: observed %.0f, expected %.2f\n", g.observed[g.noCell()],
                  g.expected[g.noCell()]);
    const std::vector<double>* tables[2] = {&g.observed, &g.expected};
    for (int t = 0; t < 2; ++t) {
        out << (t == 0 ? "# observed\n" : "# expected\n");
        for (int i = 0; i < g.rows; ++i) {
            for (int j = 0; j < g.cols; ++j)
                out << format(t == 0 ? "%.0f " : "%.6g ", (*tables[t])[size_t(i) * g.cols + j]);
            out << "\n";
        }
    }
}

// Counts of samples that void the test whatever the statistic says.
struct SampleFaults {
    long nonFinite = 0, nonUnit = 0;
};

std::string faultReport(const SampleFaults& f, long invalidPdf, double firstInvalidPdf) {
    std::string s;
    if (f.nonFinite) s += format("\n  %ld samples were NaN or Inf: rejected", f.nonFinite);
    if (f.nonUnit) s += format("\n  %ld samples were not unit vectors (| |w| - 1 | > 1e-3): rejected", f.nonUnit);
    if (invalidPdf)
        s += format("\n  the pdf was NaN, Inf or negative at %ld integration points (first value %g): rejected",
                    invalidPdf, firstInvalidPdf);
    return s;
}

ChiSquareResult finish(ChiSquareResult r, const SampleFaults& faults, long invalidPdf, double firstInvalidPdf,
                       const std::string& dumpPath, const std::string& header, const Grid& g) {
    std::string extra = faultReport(faults, invalidPdf, firstInvalidPdf);
    if (!extra.empty()) r.passed = false, r.report += extra;
    if (!r.passed) dumpTables(dumpPath, header, g, r);
    if (!r.passed && !dumpPath.empty()) r.report += "\n  tables written to " + dumpPath;
    return r;
}

std::string checkSamplerArgs(int rows, int cols, int samples, double alpha) {
    if (rows < 1 || cols < 1 || samples < 1)
        return format("chi-square: %d x %d cells and %d samples (all must be positive): rejected", rows, cols, samples);
    if (!(alpha > 0.0 && alpha < 1.0)) return format("chi-square: alpha %g not in (0, 1): rejected", alpha);
    return "";
}

}  // namespace

// ---------------------------------------------------------------------------------------------

// alpha' = 1 - (1 - alpha)^(1/m), computed as -expm1(log1p(-alpha) / m) to keep small levels exact.
double sidak(double alpha, int m) { return -std::expm1(std::log1p(-alpha) / std::max(m, 1)); }

// P(X >= x) for X ~ chi^2_k is Q(k/2, x/2).
double chiSquareSurvival(double x, int dof) {
    if (dof < 1) return std::numeric_limits<double>::quiet_NaN();
    if (x <= 0.0) return 1.0;
    return gammaQ(0.5 * dof, 0.5 * x);
}

// P(|T| >= |t|) for T ~ Student(nu) is I_{nu/(nu+t^2)}(nu/2, 1/2). Beyond nu = 1e7 the normal
// tail is used (they differ by O(1/nu), and lgamma loses digits at such arguments).
double studentTwoSided(double t, double dof) {
    if (!(dof > 0.0) || std::isnan(t)) return std::numeric_limits<double>::quiet_NaN();
    if (std::isinf(t)) return 0.0;
    if (dof > 1e7) return normalTwoSided(t);
    const double t2 = t * t;
    return betaI(0.5 * dof, 0.5, dof / (dof + t2), t2 / (dof + t2));
}

// P(|Z| >= |z|) = erfc(|z| / sqrt(2)).
double normalTwoSided(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

ChiSquareResult chiSquare(const std::vector<double>& observed, const std::vector<double>& expected, double alpha,
                          double minExpected) {
    return pearson(observed, expected, alpha, minExpected, [](size_t i) { return format("cell %zu", i); });
}

ChiSquareResult chiSquareSphere(const std::function<Vec3(const Vec2&)>& sample,
                                const std::function<double(const Vec3&)>& pdf, int thetaBins, int phiBins, int samples,
                                uint64_t seed, double alpha, const std::string& dumpPath) {
    std::string bad = checkSamplerArgs(thetaBins, phiBins, samples, alpha);
    if (!bad.empty()) return rejectWith(bad);
    Grid g(thetaBins, phiBins);  // row: cos(theta) bin from -1 up, column: phi bin from 0
    const double dz = 2.0 / thetaBins, dphi = 2.0 * kPiD / phiBins;

    // Observed: bin each sample by (cos theta, phi); zero vectors count in no cell.
    SampleFaults faults;
    Rng rng(seed, 0);
    for (int s = 0; s < samples; ++s) {
        const Vec3 w = sample(rng.uniform2());
        if (!(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z))) {
            ++faults.nonFinite;
            continue;
        }
        const double x = w.x, y = w.y, z = w.z, len = std::sqrt(x * x + y * y + z * z);
        if (len == 0.0) {
            g.observed[g.noCell()] += 1.0;
            continue;
        }
        if (std::abs(len - 1.0) > 1e-3) ++faults.nonUnit;
        double phi = std::atan2(y, x);
        if (phi < 0.0) phi += 2.0 * kPiD;
        const int i = std::clamp(int((z / len + 1.0) / dz), 0, thetaBins - 1);
        const int j = std::clamp(int(phi / dphi), 0, phiBins - 1);
        g.observed[size_t(i) * phiBins + j] += 1.0;
    }

    // Expected: N times the integral of the pdf over each cell.
    CheckedPdf<Vec3> checked{pdf};
    double integral = 0.0;
    for (int i = 0; i < thetaBins; ++i)
        for (int j = 0; j < phiBins; ++j) {
            const double p = integrateSphereCell(checked, -1.0 + i * dz, -1.0 + (i + 1) * dz, j * dphi, (j + 1) * dphi);
            integral += p;
            g.expected[size_t(i) * phiBins + j] = double(samples) * p;
        }
    g.expected[g.noCell()] = std::max(0.0, double(samples) * (1.0 - integral));

    auto name = [&](size_t c) {
        if (c == g.noCell()) return std::string("the invalid samples (zero vectors)");
        const int i = int(c / phiBins), j = int(c % phiBins);
        return format("cell (cos(theta) bin %d [%.3f, %.3f], phi bin %d [%.3f, %.3f])", i, -1.0 + i * dz,
                      -1.0 + (i + 1) * dz, j, j * dphi, (j + 1) * dphi);
    };
    ChiSquareResult r = pearson(g.observed, g.expected, alpha, 5.0, name, g.noCell());
    if (!r.passed) r.report = integralReport(integral, "the sphere") + r.report;
    r.report += format("; pdf integral over the sphere %.6f, %.0f invalid samples of %d", integral,
                       g.observed[g.noCell()], samples);
    const std::string header = format(
        "chi-square over the sphere: observed then expected counts, %d rows (cos(theta) bins from -1 to 1) x "
        "%d columns (phi bins from 0 to 2 pi)",
        thetaBins, phiBins);
    return finish(r, faults, checked.invalid, checked.firstInvalid, dumpPath, header, g);
}

ChiSquareResult chiSquarePlanar(const std::function<Vec2(const Vec2&)>& sample,
                                const std::function<double(const Vec2&)>& pdf, const Vec2& lo, const Vec2& hi, int bins,
                                int samples, uint64_t seed, double alpha, const std::string& dumpPath) {
    std::string bad = checkSamplerArgs(bins, bins, samples, alpha);
    if (!bad.empty()) return rejectWith(bad);
    if (!(hi.x > lo.x && hi.y > lo.y)) return rejectWith("chi-square: empty rectangle [lo, hi]: rejected");
    Grid g(bins, bins);  // row: y bin, column: x bin
    const double dx = (double(hi.x) - lo.x) / bins, dy = (double(hi.y) - lo.y) / bins;

    // Observed: points outside [lo, hi] count in no cell.
    SampleFaults faults;
    Rng rng(seed, 0);
    for (int s = 0; s < samples; ++s) {
        const Vec2 p = sample(rng.uniform2());
        if (!(std::isfinite(p.x) && std::isfinite(p.y))) {
            ++faults.nonFinite;
            continue;
        }
        if (p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y) {
            g.observed[g.noCell()] += 1.0;
            continue;
        }
        const int i = std::clamp(int((p.y - double(lo.y)) / dy), 0, bins - 1);
        const int j = std::clamp(int((p.x - double(lo.x)) / dx), 0, bins - 1);
        g.observed[size_t(i) * bins + j] += 1.0;
    }

    CheckedPdf<Vec2> checked{pdf};
    double integral = 0.0;
    for (int i = 0; i < bins; ++i)
        for (int j = 0; j < bins; ++j) {
            const Box cell{lo.x + j * dx, lo.x + (j + 1) * dx, lo.y + i * dy, lo.y + (i + 1) * dy};
            const double p = integratePlanarCell(checked, cell, lo, hi);
            integral += p;
            g.expected[size_t(i) * bins + j] = double(samples) * p;
        }
    g.expected[g.noCell()] = std::max(0.0, double(samples) * (1.0 - integral));

    auto name = [&](size_t c) {
        if (c == g.noCell()) return std::string("the samples outside [lo, hi]");
        const int i = int(c / bins), j = int(c % bins);
        return format("cell (x bin %d [%.4g, %.4g], y bin %d [%.4g, %.4g])", j, lo.x + j * dx, lo.x + (j + 1) * dx, i,
                      lo.y + i * dy, lo.y + (i + 1) * dy);
    };
    ChiSquareResult r = pearson(g.observed, g.expected, alpha, 5.0, name, g.noCell());
    if (!r.passed) r.report = integralReport(integral, "the rectangle") + r.report;
    r.report += format("; pdf integral over the rectangle %.6f, %.0f samples outside of %d", integral,
                       g.observed[g.noCell()], samples);
    const std::string header = format(
        "chi-square over [%g, %g] x [%g, %g]: observed then expected counts, %d rows (y bins, increasing) x "
        "%d columns (x bins, increasing)",
        lo.x, hi.x, lo.y, hi.y, bins, bins);
    return finish(r, faults, checked.invalid, checked.firstInvalid, dumpPath, header, g);
}

double integrateSphere(const std::function<double(const Vec3&)>& f) {
    constexpr int kThetaBins = 51, kPhiBins = 102;
    CheckedPdf<Vec3> checked{f};
    double total = 0.0;
    for (int i = 0; i < kThetaBins; ++i)
        for (int j = 0; j < kPhiBins; ++j)
            total += integrateSphereCell(checked, -1.0 + 2.0 * i / kThetaBins, -1.0 + 2.0 * (i + 1) / kThetaBins,
                                         2.0 * kPiD * j / kPhiBins, 2.0 * kPiD * (j + 1) / kPhiBins);
    return checked.invalid ? std::numeric_limits<double>::quiet_NaN() : total;
}

double integratePlanar(const std::function<double(const Vec2&)>& f, const Vec2& lo, const Vec2& hi) {
    CheckedPdf<Vec2> checked{f};
    double total = integratePlanarCell(checked, Box{lo.x, hi.x, lo.y, hi.y}, lo, hi);
    return checked.invalid ? std::numeric_limits<double>::quiet_NaN() : total;
}

// ---------------------------------------------------------------------------------------------
// 5. Estimators.

// Welford's update: delta = x - mean_{n-1}; mean_n = mean_{n-1} + delta / n;
// M2_n = M2_{n-1} + delta (x - mean_n); s^2 = M2 / (n - 1).
void Welford::add(double x) {
    ++n;
    const double delta = x - mean;
    mean += delta / double(n);
    m2 += delta * (x - mean);
}

double Welford::variance() const { return n > 1 ? m2 / double(n - 1) : 0.0; }

double Welford::stdError() const { return n > 0 ? std::sqrt(variance() / double(n)) : kInfD; }

void ImageWelford::add(const Image& img) {
    if (channels.empty()) {
        width = img.width;
        height = img.height;
        channels.resize(img.pixels.size() * 3);
    }
    if (img.width != width || img.height != height) throw std::invalid_argument("ImageWelford: images of two sizes");
    for (size_t i = 0; i < img.pixels.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) channels[i * 3 + size_t(ch)].add(double(img.pixels[i][ch]));
}

Image ImageWelford::mean() const {
    Image m(width, height);
    for (size_t i = 0; i < m.pixels.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) m.pixels[i][ch] = float(channels[i * 3 + size_t(ch)].mean);
    return m;
}

Image ImageWelford::varianceOfMean() const {
    Image v(width, height);
    for (size_t i = 0; i < v.pixels.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const Welford& w = channels[i * 3 + size_t(ch)];
            v.pixels[i][ch] = w.n > 0 ? float(w.variance() / double(w.n)) : 0.0f;
        }
    return v;
}

TTestResult tTest(const Welford& samples, double reference, double alpha, double maxRelStdError) {
    TTestResult r;
    r.mean = samples.mean;
    r.reference = reference;
    r.stdError = samples.stdError();
    if (samples.n < 2 || !std::isfinite(samples.mean) || !std::isfinite(samples.m2)) {
        r.report = format("t-test: %llu samples, mean %g, M2 %g (need >= 2 samples and finite values): rejected",
                          (unsigned long long)samples.n, samples.mean, samples.m2);
        return r;
    }
    const double dof = double(samples.n - 1);
    if (r.stdError == 0.0) {
        // No noise: the mean must be the reference up to rounding.
        const bool equal = std::abs(r.mean - reference) <= 1e-12 * std::max(std::abs(r.mean), std::abs(reference));
        r.t = equal ? 0.0 : kInfD;
        r.pValue = equal ? 1.0 : 0.0;
        r.passed = equal;
        r.report = format("t-test: zero variance, mean %.12g %s reference %.12g (relative 1e-12): %s", r.mean,
                          equal ? "==" : "!=", reference, equal ? "accepted" : "rejected");
        return r;
    }
    r.t = (r.mean - reference) / r.stdError;  // t = (mean - ref) / sqrt(s^2 / n), dof n - 1
    r.pValue = studentTwoSided(r.t, dof);
    r.passed = r.pValue >= alpha;
    r.report = format(
        "t-test: mean %.6g vs reference %.6g, std error %.3g, t = %.3f, dof %.0f, p = %.3g %s alpha %.3g: %s", r.mean,
        reference, r.stdError, r.t, dof, r.pValue, r.passed ? ">=" : "<", alpha, r.passed ? "accepted" : "rejected");
    if (maxRelStdError > 0.0) {
        const double limit = maxRelStdError * std::abs(reference);
        const bool powerful = r.stdError <= limit;
        r.report +=
            format("\n  power: std error %.3g %s %.3g = %g x |reference|: %s", r.stdError, powerful ? "<=" : ">", limit,
                   maxRelStdError, powerful ? "enough samples" : "too noisy to judge (rejected)");
        r.passed = r.passed && powerful;
    }
    return r;
}

ZTestResult zTestImages(const Image& a, const Image& varA, const Image& b, const Image& varB, double alpha,
                        double requiredFraction, double varianceFloor) {
    ZTestResult r;
    const auto sameSize = [&](const Image& im) {
        return im.width == a.width && im.height == a.height && im.pixels.size() == a.pixels.size();
    };
    if (!sameSize(varA) || !sameSize(b) || !sameSize(varB) || a.pixels.empty()) {
        r.report =
            format("z-test: image sizes differ or are empty (a %dx%d, varA %dx%d, b %dx%d, varB %dx%d): rejected",
                   a.width, a.height, varA.width, varA.height, b.width, b.height, varB.width, varB.height);
        return r;
    }
    struct Channel {
        int x, y, c;
        double a, b, z;
    };
    std::vector<Channel> channels;
    r.total = int(a.pixels.size()) * 3;
    const double level = sidak(alpha, r.total);  // per channel
    channels.reserve(size_t(r.total));
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double va = a.at(x, y)[c], vb = b.at(x, y)[c];
                const double var = double(varA.at(x, y)[c]) + double(varB.at(x, y)[c]) + varianceFloor;
                double z = std::abs(va - vb) / std::sqrt(var);     // z = |a - b| / sqrt(varA + varB + floor)
                if (!std::isfinite(z) || !(var > 0.0)) z = kInfD;  // NaN/Inf values or variances fail
                if (!(normalTwoSided(z) >= level)) ++r.failed;
                channels.push_back({x, y, c, va, vb, z});
            }
    r.fractionPassed = double(r.total - r.failed) / r.total;
    r.passed = r.fractionPassed >= requiredFraction;
    r.report = format(
        "z-test: %d of %d pixel channels fail at per-channel alpha %.3g (Sidak of %.3g), %.4f%% pass "
        "%s required %.4f%%: %s",
        r.failed, r.total, level, alpha, 100.0 * r.fractionPassed, r.passed ? ">=" : "<", 100.0 * requiredFraction,
        r.passed ? "accepted" : "rejected");
    const size_t k = std::min<size_t>(5, channels.size());
    std::partial_sort(channels.begin(), channels.begin() + k, channels.end(),
                      [](const Channel& p, const Channel& q) { return p.z > q.z; });
    r.report += "\n  worst:";
    for (size_t i = 0; i < k; ++i)
        r.report += format(" (x %d, y %d, %c) a %.5g b %.5g z %.2f;", channels[i].x, channels[i].y,
                           "RGB"[channels[i].c], channels[i].a, channels[i].b, channels[i].z);
    if (!r.passed) r.report += "\n  " + writeFailedImages(a, varA, b, varB);
    return r;
}

namespace {
std::string& currentTestName() {
    static std::string name;
    return name;
}
std::map<std::string, int>& imagesWritten() {
    static std::map<std::string, int> count;
    return count;
}
}  // namespace

void setCurrentTestName(const std::string& name) { currentTestName() = name; }

std::string writeFailedImages(const Image& a, const Image& varA, const Image& b, const Image& varB) {
    // A folder name from the test's name: letters and digits, the rest one '-', at most 40 characters.
    std::string slug;
    for (char ch : currentTestName().empty() ? std::string("image-test") : currentTestName()) {
        const unsigned char u = static_cast<unsigned char>(ch);
        if (std::isalnum(u)) slug += char(std::tolower(u));
        else if (!slug.empty() && slug.back() != '-') slug += '-';
        if (slug.size() >= 40) break;
    }
    while (!slug.empty() && slug.back() == '-') slug.pop_back();
    if (const int n = ++imagesWritten()[slug]; n > 1) slug += "-" + std::to_string(n);
    // Into the build tree (build/failed-images/), else the test's working folder (the grader's
    // scratch folder).
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::path folder = fs::path(testfiles::binaryDir()) / "failed-images" / slug;
    if (!fs::create_directories(folder, ec) && !fs::is_directory(folder, ec)) {
        folder = fs::path("failed-images") / slug;
        fs::create_directories(folder, ec);
    }
    const std::string base = folder.string() + "/";
    try {
        writePFM(base + "a.pfm", a);
        if (!varA.pixels.empty()) writePFM(base + "a-variance.pfm", varA);
        writePFM(base + "b.pfm", b);
        if (!varB.pixels.empty()) writePFM(base + "b-variance.pfm", varB);
    } catch (const std::exception& e) { return std::string("(the two images could not be written: ") + e.what() + ")"; }
    // Named from the source tree's root when the build tree is inside it (build/...), so that the
    // command runs as printed from there.
    std::string shown = base;
    const std::string root = std::string(testfiles::sourceDir()) + "/";
    if (shown.compare(0, root.size(), root) == 0) shown = shown.substr(root.size());
    return "to see where a and b differ: ./build/pathspace compare " + shown + "a.pfm " + shown + "b.pfm" +
           (varA.pixels.empty() ? "" : " --variance-a " + shown + "a-variance.pfm") +
           (varB.pixels.empty() ? "" : " --variance-b " + shown + "b-variance.pfm") + " --out " + shown + "compare.png";
}

}  // namespace ps::stats
