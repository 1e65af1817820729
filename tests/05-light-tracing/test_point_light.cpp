// Lesson 5, graded: a point light of intensity I = R^2 at the centre of a diffuse sphere of radius
// R (albedo a = 0.5), the camera inside, looking away from the light (so the light itself is not
// in the image). Every pixel measures L = a I / (pi R^2) (1 - a^D) / (1 - a) with at most D
// bounces (lesson 3's Eq. 3.9), the same at radii 1e-3, 1 and 1e3. The light tracer's samples
// are its iterations (each an independent estimate of the whole image): t-test of the mean over
// the 16 x 16 pixels, at level alpha() (lesson05.h), standard error <= 0.5 % of L.
#include "lesson05.h"
#include "seed.h"

using namespace lesson05;

TEST_CASE(
    "light tracing: a point light in a sphere gives the analytic radiance at radii 1e-3, 1 and 1e3 (t-test) [2 pts]") {
    constexpr int D = 6, kIterations = 2000;
    constexpr double a = 0.5;
    uint64_t seed = 5401;
    for (double R : {1e-3, 1.0, 1e3}) {
        std::ostringstream s;
        s << "camera eye 0 0 " << num(-0.5 * R) << "  target 0 0 " << num(-R) << "  fov 90  resolution 16 16\n"
          << "material wall diffuse albedo 0.5 0.5 0.5\n"
          << "sphere center 0 0 0  radius " << num(R) << "  material wall\n"
          << "pointlight position 0 0 0  intensity " << num(R * R) << " " << num(R * R) << " " << num(R * R) << "\n"
          << "render maxdepth " << D << "\n";
        const ps::Scene scene =
            ps::parseScene(s.str(), "point light in a sphere of radius " + num(R) + " (test_point_light.cpp)");
        std::unique_ptr<ps::Integrator> lt = ps::makeIntegrator("lt");
        ps::stats::Welford w;
        ps::SampleStats stats;
        ps::Image it(16, 16);
        for (int k = 0; k < kIterations; ++k) {
            std::fill(it.pixels.begin(), it.pixels.end(), Color(0.0f));
            lt->renderIteration(scene, uint32_t(k), ps::testseed::seed(seed), it, stats);
            w.add(total(it) / (3.0 * 256.0));
        }
        ++seed;
        const double expected = a * (R * R) / (3.14159265358979323846 * R * R) * (1.0 - std::pow(a, D)) / (1.0 - a);
        CHECK_MESSAGE(stats.bad() == 0, "radius " << R << ": expected 0 NaN or Inf samples, got " << stats.bad());
        const ps::stats::TTestResult t = ps::stats::tTest(w, expected, alpha(), 0.005);
        CHECK_MESSAGE(
            t.passed,
            "lt, point light (I = R^2) in a diffuse sphere of radius "
                << R << " (albedo 0.5, maxdepth " << D << "), 16 x 16 pixels, " << kIterations
                << " iterations of 256 light paths: expected every pixel to be L = a I / (pi R^2) (1 - a^D) / (1 - a) = "
                << num(expected) << ", got a mean of " << num(t.mean) << " +- " << num(t.stdError) << "\n  "
                << t.report);
    }
}
