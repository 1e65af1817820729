// Lesson 5, graded: a point light seen directly through the pinhole. Its 0-bounce connection is
// a finite measurement that lands in one pixel (Eq. 5.5 with y0 a delta position: no cosine at
// the light, Le = I): that pixel is I W_e^(j) cos(theta_e) / d^2 = I (w h) / (A cos^3 theta_e d^2)
// exactly, every other pixel is black (the scene has nothing else). Found missing by
// scripts/mutants.sh: the other point-light scenes of the lesson keep the light out of view.
#include <cmath>
#include "lesson05.h"
#include "seed.h"

using namespace lesson05;

TEST_CASE("light tracing: a point light in view lights exactly its pixel with I W_e cos / d^2 (Eq. 5.5) [1 pt]") {
    // 16 x 16 pixels, fov 90 (image plane area A = 4 at distance 1); the light at distance 2
    // along the ray through the centre of pixel (5, 9).
    const Vec3 eye(0.0f), target(0.0f, 0.0f, 1.0f), up(0.0f, 1.0f, 0.0f);
    const ps::Camera camera(eye, target, up, 90.0f, 16, 16);
    const ps::Ray through = camera.generateRay(Vec2(5.5f, 9.5f));
    const Vec3 p = eye + 2.0f * through.d;
    std::ostringstream s;
    s.precision(9);
    s << "camera eye 0 0 0  target 0 0 1  up 0 1 0  fov 90  resolution 16 16\n"
      << "pointlight position " << p.x << " " << p.y << " " << p.z << "  intensity 1 2 3\n";
    const ps::Scene scene = ps::parseScene(s.str(), "a point light in view (test_point_in_view.cpp)");
    const Render r = render(scene, "lt", 4, ps::testseed::seed(5801));
    const double cosE = double(glm::dot(glm::normalize(glm::dvec3(p)), glm::dvec3(0.0, 0.0, 1.0)));
    const double d2 = glm::dot(glm::dvec3(p), glm::dvec3(p));
    const double expected = 16.0 * 16.0 / (4.0 * cosE * cosE * cosE * d2);  // per unit of I
    int others = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            if (!(x == 5 && y == 9) && sum(r.mean.at(x, y)) != 0.0) ++others;
    const Color got = r.mean.at(5, 9);
    const bool ok = std::abs(got.r - expected) <= 1e-3 * expected &&
                    std::abs(got.g - 2.0 * expected) <= 2e-3 * expected &&
                    std::abs(got.b - 3.0 * expected) <= 3e-3 * expected;
    CHECK_MESSAGE(ok, "point light (I = 1 2 3) at distance 2 in view through pixel (5, 9): expected that pixel to be "
                          << "I (w h) / (A cos^3 d^2) = (" << expected << ", " << 2.0 * expected << ", "
                          << 3.0 * expected << "), got (" << got.r << ", " << got.g << ", " << got.b << ") (ratio "
                          << got.r / expected
                          << "; below 1 and noisy: a cosine taken at the point light, which has no surface?)");
    CHECK_MESSAGE(others == 0,
                  "expected every other pixel black (nothing else in the scene), got " << others << " lit");
}
