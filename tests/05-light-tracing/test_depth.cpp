// Lesson 5, graded: the light tracer's maximum depth (Eq. 5.1-5.4). In the point-light sphere of
// test_point_light.cpp at radius 1, maxdepth 1 and 2 must give L = a I / pi (1 - a^D) / (1 - a),
// that is a / pi and 1.5 a / pi: a light path connects to the camera at every one of its D
// bounces, the last one included. Found missing by scripts/mutants.sh: at maxdepth 6 the last
// bounce is only 1.6 % of the image. t-tests at level alpha() (lesson05.h), standard error
// <= 1 % of L (the mistake it is for is off by 100 % or 33 %).
#include "lesson05.h"
#include "seed.h"

using namespace lesson05;

TEST_CASE(
    "light tracing: maxdepth 1 and 2 connect every bounce, the last one included (point light in a sphere, t-test) [1 pt]") {
    constexpr int kIterations = 3000;
    constexpr double a = 0.5;
    uint64_t seed = 5451;
    for (int D : {1, 2}) {
        std::ostringstream s;
        s << "camera eye 0 0 -0.5  target 0 0 -1  fov 90  resolution 16 16\n"
          << "material wall diffuse albedo 0.5 0.5 0.5\n"
          << "sphere center 0 0 0  radius 1  material wall\n"
          << "pointlight position 0 0 0  intensity 1 1 1\n"
          << "render maxdepth " << D << "\n";
        const ps::Scene scene =
            ps::parseScene(s.str(), "point light in a sphere, maxdepth " + num(D) + " (test_depth.cpp)");
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
        const double expected = a / 3.14159265358979323846 * (1.0 - std::pow(a, D)) / (1.0 - a);
        CHECK_MESSAGE(stats.bad() == 0, "maxdepth " << D << ": expected 0 NaN or Inf samples, got " << stats.bad());
        const ps::stats::TTestResult t = ps::stats::tTest(w, expected, alpha(), 0.01);
        CHECK_MESSAGE(t.passed,
                      "lt, point light (I = 1) in a diffuse sphere of radius 1 (albedo 0.5), maxdepth "
                          << D << ": expected every pixel to be L = a I / pi (1 - a^D) / (1 - a) = " << num(expected)
                          << ", got a mean of " << num(t.mean) << " +- " << num(t.stdError) << " (ratio "
                          << num(t.mean / expected) << "; " << (D == 1 ? "0" : "2/3")
                          << ": the last bounce not connected, the maximum depth off by one?)\n  " << t.report);
    }
}
