// Lesson 5, graded: light tracing from the background in an open scene (Eq. 5.1-5.5 with the
// background as the light: particles start on the disk of sampleEmission, outside the scene's
// bounding sphere, and most of them leave the scene). A diffuse floor (albedo a) under a constant
// sky of radiance Lb and nothing else: every point of the floor sees the whole sky above it and
// nothing of itself, so the radiance it sends to the camera is exactly a Lb (the rendering
// equation with E = pi Lb). Particles that reach the floor from below give nothing towards the
// camera above it. The camera sees the floor in the lower part of the image and the sky above
// it: the sky seen directly is not the light tracer's (no point to connect, section 1.6), so
// those pixels are exactly black; a point on the background's disk connected to the camera like
// a lamp's lights them.
// t-test of the mean over the floor's pixels at level alpha() (lesson05.h), standard error <= 1 %
// of the expected (what it is for: particles lost or shown after they left the scene, off by far
// more); the sky's pixels exactly 0.
#include "lesson05.h"
#include "seed.h"

using namespace lesson05;

TEST_CASE(
    "light tracing: a floor under the sky alone has radiance albedo times the sky's (open scene, t-test) [1 pt]") {
    // Floor [-1, 1]^2 at y = 0 (albedo 0.5), sky (1, 2, 3), camera 1 above the floor's edge
    // looking at its centre, 16 x 16 pixels: about the lower half of the image is floor.
    const ps::Scene scene = ps::parseScene(
        "camera eye 0 0.6 -2  target 0 0 0  fov 50  resolution 16 16\n"
        "material floor diffuse albedo 0.5 0.5 0.5\n"
        "quad -1 0 -1  -1 0 1  1 0 1  1 0 -1  material floor\n"
        "background radiance 1 2 3\n"
        "render maxdepth 8\n",
        "a floor under the sky (test_background.cpp)");
    const std::vector<bool> floor =
        ps::testrender::pixelsWhere(scene, true, [](bool hit, const ps::SurfacePoint&) { return hit; });
    const std::vector<bool> sky =
        ps::testrender::pixelsWhere(scene, true, [](bool hit, const ps::SurfacePoint&) { return !hit; });
    int nFloor = 0, nSky = 0;
    for (size_t i = 0; i < floor.size(); ++i) nFloor += floor[i], nSky += sky[i];
    REQUIRE_MESSAGE((nFloor >= 40 && nSky >= 40), "test setup: " << nFloor << " floor and " << nSky << " sky pixels");
    constexpr int kIterations = 3000;
    std::unique_ptr<ps::Integrator> lt = ps::makeIntegrator("lt");
    ps::stats::Welford w;
    ps::SampleStats stats;
    ps::Image it(16, 16);
    double skyLight = 0.0;
    for (int k = 0; k < kIterations; ++k) {
        std::fill(it.pixels.begin(), it.pixels.end(), Color(0.0f));
        lt->renderIteration(scene, uint32_t(k), ps::testseed::seed(5901), it, stats);
        double onFloor = 0.0;
        for (size_t i = 0; i < it.pixels.size(); ++i) {
            if (floor[i]) onFloor += sum(it.pixels[i]);
            if (sky[i]) skyLight += sum(it.pixels[i]);
        }
        w.add(onFloor / (3.0 * nFloor));
    }
    const double expected = 0.5 * (1.0 + 2.0 + 3.0) / 3.0;  // a Lb, averaged over the channels
    CHECK_MESSAGE(stats.bad() == 0, "expected 0 NaN or Inf samples, got " << stats.bad());
    const ps::stats::TTestResult t = ps::stats::tTest(w, expected, alpha(), 0.01);
    CHECK_MESSAGE(t.passed,
                  "lt, a diffuse floor (albedo 0.5) under a sky of radiance (1, 2, 3), nothing else: "
                  "expected every pixel that sees only the floor to be a Lb, a mean of "
                      << num(expected) << ", got " << num(t.mean) << " +- " << num(t.stdError) << " (ratio "
                      << num(t.mean / expected) << ")\n  " << t.report);
    CHECK_MESSAGE(skyLight == 0.0, "the " << nSky << " pixels that see only the sky: expected exactly 0 (the "
                                          << "background has no point to connect to the camera), got R + G + B = "
                                          << skyLight / kIterations << " per iteration");
}
