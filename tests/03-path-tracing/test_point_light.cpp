// Lesson 3, graded: a point light of intensity I at the centre of a diffuse sphere of radius R
// (albedo a = 0.5, camera inside). Every ray sees L = a I / (pi R^2) (1 - a^D) / (1 - a) with
// at most D bounces (Eq. 3.9): the first bounce is the direct light, each further bounce
// multiplies by a. With I = R^2 the value does not depend on R: the radii 1e-3, 1 and 1e3 test
// that nothing in the estimators depends on the scale of the scene (ray offsets, the 1/d^2 of
// a point light). BSDF sampling alone never hits a point light, so only pt-nee and pt are tested.
// t-tests at level alpha() (lesson03.h), standard error <= 0.3 % of L.
#include "lesson03.h"

using namespace lesson03;

namespace {

void checkPointLight(const Estimator& e, uint64_t seed) {
    constexpr int D = 6;
    constexpr float a = 0.5f;
    for (float R : {1e-3f, 1.0f, 1e3f}) {
        const ps::Scene scene = pointInSphere(R, a);
        const double expected = 3.0 * pointInSphereRadiance(a, double(R) * R, R, D);
        const Samples s = sampleLi(scene, e, D, 40000, seed++);
        CHECK_MESSAGE(s.bad == 0, e.name << ", point light in a sphere of radius " << R
                                         << ": expected 0 NaN or Inf samples, got " << s.bad);
        const ps::stats::TTestResult t = ps::stats::tTest(s.w, expected, alpha(), 0.003);
        CHECK_MESSAGE(t.passed, e.name << ", point light (I = R^2) in a diffuse sphere of radius " << R
                                       << " (albedo 0.5, maxdepth " << D
                                       << "): expected L = a I / (pi R^2) (1 - a^D) / (1 - a) = " << expected / 3.0
                                       << " per channel (R + G + B = " << expected << "), got R + G + B = " << t.mean
                                       << " +- " << t.stdError << "\n  " << t.report);
    }
}

}  // namespace

TEST_CASE(
    "path tracing: a point light in a sphere gives the same radiance at radii 1e-3, 1 and 1e3, next-event estimation (t-test) [1 pt]") {
    checkPointLight(estimators()[1], 401);
}

TEST_CASE(
    "path tracing: a point light in a sphere gives the same radiance at radii 1e-3, 1 and 1e3, MIS (t-test) [1 pt]") {
    checkPointLight(estimators()[2], 411);
}
