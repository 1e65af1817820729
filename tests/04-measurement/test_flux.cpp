// Lesson 4, graded: the flux through a region S, measured from the lights (Eq. 4.12, 4.13), against
// the analytic values of Eq. 4.14 (a point light: its intensity times the solid angle S subtends)
// and Eq. 4.15 (a square area light over a square patch: pi A Le times the form factor of two
// directly opposed squares). Each scene has a second, brighter light facing away from S: its
// particles never reach S, but they are chosen in proportion to its power, so the estimate is
// right only if every particle is divided by the probability of its light.
// t-tests at level alpha() (lesson04.h) with a power check (standard error <= 0.5 % of the flux).
#include "lesson04.h"
#include "seed.h"

using namespace lesson04;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The light that never reaches S: a 2 x 2 square high above everything, facing up.
const char* const kDecoy = "quad -1 8 -1  -1 8 1  1 8 1  1 8 -1  emission 1 1 1\n";

struct FluxResult {
    ps::stats::Welford w;
    int bad = 0;
};
FluxResult measureFlux(const ps::Scene& scene, int n, uint64_t seed) {
    const ps::Region S = ps::regionWithMaterial(scene, "sensor");
    FluxResult r;
    for (int i = 0; i < n; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(seed), 0, uint32_t(i));
        const Color c = ps::fluxParticle(scene, S, rng);
        if (!ps::isFinite(c)) {
            ++r.bad;
            continue;
        }
        r.w.add(sum(c));
    }
    return r;
}

void checkFlux(const std::string& what, const FluxResult& r, double expected, int n) {
    CHECK_MESSAGE(r.bad == 0, what << ": expected 0 NaN or Inf particles, got " << r.bad);
    const ps::stats::TTestResult t = ps::stats::tTest(r.w, expected, alpha(), 0.005);
    CHECK_MESSAGE(t.passed, what << ", " << n << " particles: expected flux R + G + B = " << num(expected) << ", got "
                                 << num(t.mean) << " +- " << num(t.stdError) << "\n  " << t.report);
}

}  // namespace

TEST_CASE(
    "measurement: flux through a patch under a point light equals I times its solid angle (Eq. 4.14, t-test) [2 pts]") {
    // A point light of intensity I = (2, 3, 4) W/sr at height h = 1 above the rectangle
    // [-0.3, 0.7] x [-0.2, 0.5] of the plane y = 0 (off centre). The flux through it is I Omega,
    // Omega the solid angle the rectangle subtends at the light: with F(x, z) =
    // atan(x z / (h sqrt(x^2 + z^2 + h^2))) (the solid angle of the rectangle from the foot point
    // to the corner (x, z)), Omega = F(x1, z1) - F(x0, z1) - F(x1, z0) + F(x0, z0).
    const std::string text = std::string("camera eye 0 3 -4  target 0 0 0  fov 40  resolution 4 4\n") +
                             "material sensor diffuse albedo 0 0 0\n"
                             "quad -0.3 0 -0.2  -0.3 0 0.5  0.7 0 0.5  0.7 0 -0.2  material sensor\n"
                             "pointlight position 0 1 0  intensity 2 3 4\n" +
                             kDecoy;
    const ps::Scene scene = ps::parseScene(text, "point light over a patch (test_flux.cpp)");
    const double h = 1.0, x0 = -0.3, x1 = 0.7, z0 = -0.2, z1 = 0.5;
    const auto F = [&](double x, double z) { return std::atan(x * z / (h * std::sqrt(x * x + z * z + h * h))); };
    const double omega = F(x1, z1) - F(x0, z1) - F(x1, z0) + F(x0, z0);
    const int n = 2000000;
    checkFlux("point light I = (2, 3, 4) at height 1 over the patch [-0.3, 0.7] x [-0.2, 0.5] (solid angle " +
                  num(omega) + " sr)",
              measureFlux(scene, n, 4201), (2.0 + 3.0 + 4.0) * omega, n);
    // Without any light there is no flux: every particle 0 (and none drawn from a light that is not there).
    const ps::Scene dark = ps::parseScene(
        "camera eye 0 3 -4  target 0 0 0  fov 40  resolution 4 4\n"
        "material sensor diffuse albedo 0 0 0\n"
        "quad -0.3 0 -0.2  -0.3 0 0.5  0.7 0 0.5  0.7 0 -0.2  material sensor\n",
        "the patch without a light (test_flux.cpp)");
    const FluxResult none = measureFlux(dark, 100, 4203);
    CHECK_MESSAGE((none.bad == 0 && none.w.n == 100 && none.w.mean == 0.0),
                  "a scene without lights: expected every particle's flux 0, got the mean "
                      << none.w.mean << " and " << none.bad << " NaN or Inf particles");
}

TEST_CASE(
    "measurement: flux through a patch under a square area light equals pi A Le times the form factor (Eq. 4.15, t-test) [2 pts]") {
    // A 1 x 1 square light of radiance Le = (1, 2, 3) facing down at height c = 1, directly over
    // a 1 x 1 patch. The flux the patch receives is pi A Le F, F the form factor of two directly
    // opposed parallel a x b rectangles at distance c (X = a/c, Y = b/c):
    //   F = 2/(pi X Y) [ ln sqrt((1+X^2)(1+Y^2)/(1+X^2+Y^2)) + X sqrt(1+Y^2) atan(X/sqrt(1+Y^2))
    //                    + Y sqrt(1+X^2) atan(Y/sqrt(1+X^2)) - X atan X - Y atan Y ],
    // 0.19982 for X = Y = 1 (checked here against a direct numerical integration).
    const std::string text = std::string("camera eye 0 3 -4  target 0 0 0  fov 40  resolution 4 4\n") +
                             "material sensor diffuse albedo 0 0 0\n"
                             "quad -0.5 0 -0.5  -0.5 0 0.5  0.5 0 0.5  0.5 0 -0.5  material sensor\n"
                             "quad -0.5 1 -0.5  0.5 1 -0.5  0.5 1 0.5  -0.5 1 0.5  emission 1 2 3\n" +
                             kDecoy;
    const ps::Scene scene = ps::parseScene(text, "square light over a patch (test_flux.cpp)");
    const double X = 1.0, Y = 1.0;
    const double F =
        2.0 / (kPi * X * Y) *
        (0.5 * std::log((1 + X * X) * (1 + Y * Y) / (1 + X * X + Y * Y)) +
         X * std::sqrt(1 + Y * Y) * std::atan(X / std::sqrt(1 + Y * Y)) +
         Y * std::sqrt(1 + X * X) * std::atan(Y / std::sqrt(1 + X * X)) - X * std::atan(X) - Y * std::atan(Y));
    // The same form factor by a direct midpoint integration of cos cos / (pi r^2) over both squares.
    double numeric = 0.0;
    const int m = 24;
    for (int a = 0; a < m * m; ++a)
        for (int b = 0; b < m * m; ++b) {
            const double dx = ((a % m) - (b % m)) / double(m), dz = ((a / m) - (b / m)) / double(m);
            const double r2 = dx * dx + dz * dz + 1.0;
            numeric += 1.0 / (kPi * r2 * r2);
        }
    numeric /= double(m * m) * double(m * m);
    REQUIRE_MESSAGE(std::abs(numeric - F) < 1e-3,
                    "the test's own form factor: closed form " << num(F) << ", numerical " << num(numeric));
    const int n = 1200000;
    checkFlux("square light 1 x 1, Le = (1, 2, 3), at distance 1 over a 1 x 1 patch (form factor " + num(F) + ")",
              measureFlux(scene, n, 4301), (1.0 + 2.0 + 3.0) * kPi * 1.0 * F, n);
}
