// Lesson 1, graded: the warps (framework/warps.h; Eq. 1.6 and 1.8-1.13 of the lesson README).
// Each warp is checked five ways: its samples follow its own pdf (chi-square), its pdf
// integrates to 1, its pdf is the inverse Jacobian of the map (Eq. 1.6), it inverts, and its
// samples stay in (and cover) its domain. Chi-square alone cannot catch a sampler and a pdf that
// are wrong in the same way; the Jacobian test can.
#include <doctest/doctest.h>
#include <cmath>
#include <limits>
#include "lesson01.h"
#include "rng.h"
#include "seed.h"

using namespace lesson01;
using ps::kPi;

namespace {

constexpr int kThetaBins = 51, kPhiBins = 102;  // odd: the horizon lies inside a row of cells
constexpr int kPlanarBins = 51;
constexpr float kLastBelowOne = 1.0f - 0x1p-24f;  // the largest float in [0, 1)

// Pearson's chi-square of a direction warp against its own pdf over the sphere.
void chiSquareSphere(const SphereWarp& w, const std::string& file, int samples, uint64_t seed) {
    const ps::stats::ChiSquareResult r = ps::stats::chiSquareSphere(
        w.sample, [&](const Vec3& d) { return double(w.pdf(d)); }, kThetaBins, kPhiBins, samples,
        ps::testseed::seed(seed), alpha(), dumpPath(file));
    CHECK_MESSAGE(r.passed, w.name << ": the samples do not follow the pdf. " << r.report);
}

void chiSquarePlanar(const PlanarWarp& w, const std::string& file, const Vec2& lo, const Vec2& hi, int samples,
                     uint64_t seed) {
    const ps::stats::ChiSquareResult r = ps::stats::chiSquarePlanar(
        w.sample, [&](const Vec2& p) { return double(w.pdf(p)); }, lo, hi, kPlanarBins, samples,
        ps::testseed::seed(seed), alpha(), dumpPath(file));
    CHECK_MESSAGE(r.passed, w.name << ": the samples do not follow the pdf. " << r.report);
}

// 4-point Gauss-Legendre on [0, 1].
constexpr double kGx[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
constexpr double kGw[4] = {0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269};

// The integral of a pdf over the sphere, in (theta, phi) with d omega = sin(theta) d theta d phi:
// 400 theta panels (the horizon theta = pi/2 is a panel edge, a lobe of width 1/sqrt(1000) spans
// several panels), 4 Gauss points each, 64 phi points (periodic: the trapezoid rule).
double integrateOverSphere(const std::function<float(const Vec3&)>& pdf) {
    constexpr int kPanels = 400, kPhi = 64;
    const double dTheta = kPi / kPanels, dPhi = 2.0 * kPi / kPhi;
    double total = 0.0;
    for (int i = 0; i < kPanels; ++i)
        for (int g = 0; g < 4; ++g) {
            const double theta = (i + kGx[g]) * dTheta, s = std::sin(theta), z = std::cos(theta);
            double ring = 0.0;
            for (int j = 0; j < kPhi; ++j) {
                const double phi = (j + 0.5) * dPhi;
                ring += pdf(Vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(z)));
            }
            total += kGw[g] * dTheta * s * dPhi * ring;
        }
    return total;
}

// The integral of a pdf per unit area over the disk of radius 1.5 in polar coordinates
// (dA = r dr d phi), with r = 1 a panel edge.
double integrateOverDisk(const std::function<float(const Vec2&)>& pdf) {
    constexpr int kPanels = 150, kPhi = 64;
    const double dr = 1.5 / kPanels, dPhi = 2.0 * kPi / kPhi;
    double total = 0.0;
    for (int i = 0; i < kPanels; ++i)
        for (int g = 0; g < 4; ++g) {
            const double r = (i + kGx[g]) * dr;
            double ring = 0.0;
            for (int j = 0; j < kPhi; ++j) {
                const double phi = (j + 0.5) * dPhi;
                ring += pdf(Vec2(float(r * std::cos(phi)), float(r * std::sin(phi))));
            }
            total += kGw[g] * dr * r * dPhi * ring;
        }
    return total;
}

glm::dvec3 d3(const Vec3& v) { return glm::dvec3(v); }
glm::dvec2 d2(const Vec2& v) { return glm::dvec2(v); }

// Solid angle per unit area of u that the warp maps u to: |dw/du1 x dw/du2| (Eq. 1.6), by
// central differences of step h.
double jacobianSphere(const SphereWarp& w, const Vec2& u, float h) {
    const glm::dvec3 a = (d3(w.sample(u + Vec2(h, 0))) - d3(w.sample(u - Vec2(h, 0)))) / (2.0 * h);
    const glm::dvec3 b = (d3(w.sample(u + Vec2(0, h))) - d3(w.sample(u - Vec2(0, h)))) / (2.0 * h);
    return glm::length(glm::cross(a, b));
}

// Area per unit area of u: |det d(p)/d(u)|.
double jacobianPlanar(const PlanarWarp& w, const Vec2& u, float h) {
    const glm::dvec2 a = (d2(w.sample(u + Vec2(h, 0))) - d2(w.sample(u - Vec2(h, 0)))) / (2.0 * h);
    const glm::dvec2 b = (d2(w.sample(u + Vec2(0, h))) - d2(w.sample(u - Vec2(0, h)))) / (2.0 * h);
    return std::abs(a.x * b.y - a.y * b.x);
}

// Points of [0.05, 0.95]^2 on a 23 x 29 grid (different counts: few points on the diagonals).
std::vector<Vec2> interiorGrid() {
    std::vector<Vec2> us;
    for (int i = 0; i < 23; ++i)
        for (int j = 0; j < 29; ++j)
            us.emplace_back(0.05f + 0.9f * (i + 0.5f) / 23.0f, 0.05f + 0.9f * (j + 0.5f) / 29.0f);
    return us;
}

// The concentric map has kinks along the diagonals |a| = |b| of [-1, 1]^2 and at the centre,
// where central differences are meaningless.
bool nearConcentricKink(const Vec2& u, float h) {
    const float a = std::abs(2.0f * u.x - 1.0f), b = std::abs(2.0f * u.y - 1.0f);
    return std::abs(a - b) < 8.0f * h || (a < 0.05f && b < 0.05f);
}

// u for the round-trip and domain tests: one jittered point in each of 64 x 64 cells, kept
// 1e-3 away from the edges of the square (poles and the seam phi = 0 have no unique inverse).
std::vector<Vec2> jitteredGrid(uint64_t seed) {
    ps::Rng rng(ps::testseed::seed(seed));
    std::vector<Vec2> us;
    for (int i = 0; i < 64; ++i)
        for (int j = 0; j < 64; ++j) {
            const Vec2 u{(i + rng.uniform()) / 64.0f, (j + rng.uniform()) / 64.0f};
            us.push_back(glm::clamp(u, Vec2(1e-3f), Vec2(1.0f - 1e-3f)));
        }
    return us;
}

// Reports up to a few failures of a per-point check, then how many there were in all.
struct Failures {
    explicit Failures(std::string w) : what(std::move(w)) {}
    std::string what;
    int count = 0, total = 0;
    std::ostringstream first;
    void add(bool ok, const std::string& message) {
        ++total;
        if (ok) return;
        if (count++ < 4) first << "\n    " << message;
    }
    void check() {
        CHECK_MESSAGE(count == 0, what << ": " << count << " of " << total << " points fail; first:" << first.str());
    }
};

}  // namespace

// ---------------------------------------------------------------------------------------------
// Chi-square: about 1000 samples per cell where the pdf is not 0.

TEST_CASE("warps: uniform sphere matches its pdf (chi-square) [1 pt]") {
    chiSquareSphere(sphereWarps({})[0], "uniform-sphere", 1000 * kThetaBins * kPhiBins, 101);
}

TEST_CASE("warps: uniform hemisphere matches its pdf (chi-square) [1 pt]") {
    chiSquareSphere(sphereWarps({})[1], "uniform-hemisphere", 500 * kThetaBins * kPhiBins, 102);
}

TEST_CASE("warps: concentric disk matches its pdf (chi-square) [2 pts]") {
    chiSquarePlanar(planarWarps()[0], "concentric-disk", Vec2(-1.0f), Vec2(1.0f), 1000 * kPlanarBins * kPlanarBins,
                    103);
}

TEST_CASE("warps: cosine hemisphere matches its pdf (chi-square) [2 pts]") {
    chiSquareSphere(sphereWarps({})[2], "cosine-hemisphere", 500 * kThetaBins * kPhiBins, 104);
}

TEST_CASE("warps: Phong lobe matches its pdf for exponents 0, 1 and 10 (chi-square) [2 pts]") {
    const float exponents[] = {0.0f, 1.0f, 10.0f};
    for (float n : exponents) {
        const std::string file = "phong-" + std::to_string(int(n));
        chiSquareSphere(phongWarp(n), file, 500 * kThetaBins * kPhiBins, 105 + uint64_t(n));
    }
}

TEST_CASE("warps: uniform triangle matches its pdf (chi-square) [1 pt]") {
    // Barycentrics (b1, b2) in [0, 1]^2: density 2 on b1 + b2 <= 1, 0 on the other half.
    chiSquarePlanar(planarWarps()[1], "uniform-triangle", Vec2(0.0f), Vec2(1.0f), 500 * kPlanarBins * kPlanarBins, 111);
}

// ---------------------------------------------------------------------------------------------

TEST_CASE("warps: every pdf integrates to 1 over its domain [2 pts]") {
    // Over the whole sphere (a hemisphere pdf must be 0 below the horizon) and over a disk of
    // radius 1.5 (the disk pdf must be 0 outside the unit disk).
    for (const SphereWarp& w : sphereWarps({0.0f, 1.0f, 10.0f, 1000.0f})) {
        const double integral = integrateOverSphere(w.pdf);
        CHECK_MESSAGE(std::abs(integral - 1.0) < 1e-3,
                      w.name << ": the pdf integrates to " << integral << " over the sphere, expected 1 (+- 1e-3)");
    }
    const PlanarWarp disk = planarWarps()[0];
    const double integral = integrateOverDisk(disk.pdf);
    CHECK_MESSAGE(std::abs(integral - 1.0) < 1e-3, disk.name << ": the pdf integrates to " << integral
                                                             << " over the disk of radius 1.5, expected 1 (+- 1e-3)");
}

TEST_CASE("warps: pdf(sample(u)) is 1 / Jacobian of the warp (Eq. 1.6) [3 pts]") {
    // The density of the warped points is the density of u (1) over the measure the map
    // stretches a unit of u-area into: pdf(sample(u)) * |d sample / d u| = 1 everywhere.
    const float h = 1e-3f;
    for (const SphereWarp& w : sphereWarps({0.0f, 1.0f, 10.0f})) {
        const bool disky = w.name == "cosine hemisphere";
        Failures f{w.name + ": pdf(sample(u)) * Jacobian(u) should be 1 (+- 1e-2)"};
        for (const Vec2& u : interiorGrid()) {
            if (disky && nearConcentricKink(u, h)) continue;
            const Vec3 d = w.sample(u);
            const double jac = jacobianSphere(w, u, h), p = w.pdf(d);
            f.add(std::abs(p * jac - 1.0) < 1e-2, "u = " + str(u) + ": sample " + str(d) + ", pdf " + num(p) +
                                                      ", solid angle per unit u-area " + num(jac) + ", product " +
                                                      num(p * jac));
        }
        f.check();
    }
    for (const PlanarWarp& w : planarWarps()) {
        const bool disky = w.name == "concentric disk";
        Failures f{w.name + ": pdf(sample(u)) * Jacobian(u) should be 1 (+- 1e-2)"};
        for (const Vec2& u : interiorGrid()) {
            if (disky && nearConcentricKink(u, h)) continue;
            const Vec2 p = w.sample(u);
            const double jac = jacobianPlanar(w, u, h), q = w.pdf(p);
            f.add(std::abs(q * jac - 1.0) < 1e-2, "u = " + str(u) + ": sample " + str(p) + ", pdf " + num(q) +
                                                      ", area per unit u-area " + num(jac) + ", product " +
                                                      num(q * jac));
        }
        f.check();
    }
}

TEST_CASE("warps: invert(sample(u)) gives back u [2 pts]") {
    const std::vector<Vec2> us = jitteredGrid(7);
    // Exponent 1e6 is left out: float cos(alpha) is within 6e-8 of 1 there, so u.x cannot be
    // recovered to 1e-3 (the Phong test below checks that exponent).
    for (const SphereWarp& w : sphereWarps({0.0f, 1.0f, 10.0f, 1000.0f})) {
        Failures f{w.name + ": |u - invert(sample(u))| should be < 1e-3"};
        for (const Vec2& u : us) {
            const Vec3 d = w.sample(u);
            const Vec2 back = w.invert(d);
            f.add(glm::length(back - u) < 1e-3f, "u = " + str(u) + " -> " + str(d) + " -> " + str(back));
        }
        f.check();
    }
    for (const PlanarWarp& w : planarWarps()) {
        Failures f{w.name + ": |u - invert(sample(u))| should be < 1e-3"};
        for (const Vec2& u : us) {
            const Vec2 p = w.sample(u);
            const Vec2 back = w.invert(p);
            f.add(glm::length(back - u) < 1e-3f, "u = " + str(u) + " -> " + str(p) + " -> " + str(back));
        }
        f.check();
    }
    // The triangle's corner b = (0, 0) is where every u = (0, u.y) lands; its inverse is u = (0, 0)
    // (the TODO's rule for s = 0), finite: a division by s = 0 there gives NaN.
    const Vec2 corner = ps::invertUniformTriangle(Vec2(0.0f, 0.0f));
    CHECK_MESSAGE((corner.x == 0.0f && corner.y == 0.0f),
                  "uniform triangle: invert at the corner b = (0, 0) should give u = (0, 0), got "
                      << str(corner) << " (divided by s = 0?)");
}

TEST_CASE("warps: Phong lobe stays finite and right for exponents 0 to 1e6 [2 pts]") {
    // Every sample (u on the edges of [0, 1)^2 too) is a finite unit vector with z >= 0 and a
    // finite positive pdf; the pdf at the axis is (n + 1) / (2 pi); and the lobe has the right
    // width: E[1 - cos(alpha)] = 1 / (n + 2) (within 5 %, from 1e5 samples).
    const float edges[] = {0.0f, 0x1p-24f, 0.5f, kLastBelowOne};
    for (float n : {0.0f, 1.0f, 10.0f, 1000.0f, 1e6f}) {
        const SphereWarp w = phongWarp(n);
        Failures f{w.name + ": samples must be finite unit vectors with z >= 0 and a finite pdf > 0"};
        std::vector<Vec2> us;
        for (float a : edges)
            for (float b : edges) us.emplace_back(a, b);
        ps::Rng rng(ps::testseed::seed(31));
        double oneMinusCos = 0.0;
        constexpr int kSamples = 100000;
        for (int i = 0; i < kSamples; ++i) {
            const Vec3 d = w.sample(rng.uniform2());
            oneMinusCos += 1.0 - double(d.z);
            if (i < 1000) us.push_back(rng.uniform2());
        }
        for (const Vec2& u : us) {
            const Vec3 d = w.sample(u);
            const float p = w.pdf(d);
            const bool finite = std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z);
            const bool ok =
                finite && std::abs(glm::length(d) - 1.0f) < 1e-5f && d.z >= 0.0f && std::isfinite(p) && p > 0.0f;
            f.add(ok, "u = " + str(u) + ": sample " + str(d) + ", pdf " + num(p));
        }
        f.check();
        const double axis = w.pdf(Vec3(0, 0, 1)), expectedAxis = (double(n) + 1.0) / (2.0 * kPi);
        CHECK_MESSAGE(std::abs(axis - expectedAxis) <= 1e-4 * expectedAxis,
                      w.name << ": pdf at the axis (0, 0, 1): expected " << expectedAxis << ", got " << axis);
        const double below = w.pdf(Vec3(0.6f, 0.0f, -0.8f));
        CHECK_MESSAGE(below == 0.0, w.name << ": pdf below the horizon (0.6, 0, -0.8): expected 0, got " << below);
        const double mean = oneMinusCos / kSamples, expected = 1.0 / (double(n) + 2.0);
        CHECK_MESSAGE(std::abs(mean / expected - 1.0) < 0.05, w.name << ": mean of 1 - cos(alpha) over " << kSamples
                                                                     << " samples: expected " << expected
                                                                     << " (+- 5 %), got " << mean);
    }
}

TEST_CASE("warps: samples lie in their domain and cover it [1 pt]") {
    // u: a jittered grid and the corners and edge midpoints of [0, 1)^2 (kLastBelowOne for 1).
    std::vector<Vec2> us = jitteredGrid(11);
    const float edges[] = {0.0f, 0.25f, 0.5f, 0.75f, kLastBelowOne};
    for (float a : edges)
        for (float b : edges) us.emplace_back(a, b);

    for (const SphereWarp& w : sphereWarps({})) {
        Failures f{w.name +
                   (w.hemisphere ? ": samples must be unit vectors with z >= 0" : ": samples must be unit vectors")};
        Vec3 lo(ps::kInf), hi(-ps::kInf);
        for (const Vec2& u : us) {
            const Vec3 d = w.sample(u);
            lo = glm::min(lo, d), hi = glm::max(hi, d);
            f.add(std::abs(glm::length(d) - 1.0f) < 1e-5f && (!w.hemisphere || d.z >= 0.0f),
                  "u = " + str(u) + ": sample " + str(d));
        }
        f.check();
        const float zLo = w.hemisphere ? 0.01f : -0.99f;
        CHECK_MESSAGE((lo.x < -0.99f && hi.x > 0.99f && lo.y < -0.99f && hi.y > 0.99f && lo.z < zLo && hi.z > 0.99f),
                      w.name << ": the samples do not cover the " << std::string(w.hemisphere ? "hemisphere" : "sphere")
                             << ": they span " << str(lo) << " to " << str(hi) << ", expected about (-1, -1, "
                             << (w.hemisphere ? 0 : -1) << ") to (1, 1, 1)");
    }

    const PlanarWarp disk = planarWarps()[0], triangle = planarWarps()[1];
    Failures fd{"concentric disk: samples must lie in the unit disk"};
    Failures ft{"uniform triangle: barycentrics must be >= 0 with b1 + b2 <= 1"};
    Vec2 lo(ps::kInf), hi(-ps::kInf);
    float b1Max = 0.0f, b2Max = 0.0f, sumMin = ps::kInf;
    for (const Vec2& u : us) {
        const Vec2 p = disk.sample(u);
        lo = glm::min(lo, p), hi = glm::max(hi, p);
        fd.add(glm::length(p) <= 1.0f + 1e-6f, "u = " + str(u) + ": sample " + str(p));
        const Vec2 b = triangle.sample(u);
        b1Max = std::max(b1Max, b.x), b2Max = std::max(b2Max, b.y), sumMin = std::min(sumMin, b.x + b.y);
        ft.add(b.x >= 0.0f && b.y >= 0.0f && b.x + b.y <= 1.0f + 1e-6f, "u = " + str(u) + ": barycentrics " + str(b));
    }
    fd.check();
    ft.check();
    CHECK_MESSAGE((lo.x < -0.99f && hi.x > 0.99f && lo.y < -0.99f && hi.y > 0.99f),
                  "concentric disk: the samples do not cover the disk: they span "
                      << str(lo) << " to " << str(hi) << ", expected about (-1, -1) to (1, 1)");
    CHECK_MESSAGE((b1Max > 0.99f && b2Max > 0.99f && sumMin < 0.01f),
                  "uniform triangle: the samples do not reach all three corners: largest b1 "
                      << b1Max << ", largest b2 " << b2Max << ", smallest b1 + b2 " << sumMin
                      << " (expected about 1, 1 and 0)");
}
