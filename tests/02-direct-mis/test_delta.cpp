// Lesson 2, graded: the two delta cases of direct illumination (Eq. 2.4, 2.12), checked exactly.
// A BSDF sample off a mirror is a delta sample: light sampling can never produce its direction,
// so its light pdf is 0 and its MIS weight is exactly 1. A point light's sample carries
// f I cos / d^2. Found missing by scripts/mutants.sh: the other scenes of the lesson have no
// specular surface, and the point-lit Cornell box compares estimators with each other only, so a
// light pdf given to a delta sample or a missing 1/d^2 went unnoticed.
#include <cmath>
#include "lesson02.h"
#include "seed.h"

using namespace lesson02;

namespace {

// A mirror floor (y = 0) and a square lamp of radiance 1 at y = 3 facing down, where the mirror
// reflects the camera ray aimed at the origin: (0, 6, 6) -> (0, 0, 0) -> the lamp at (0, 3, -3).
const char* kMirrorScene = R"(
camera eye 0 6 6  target 0 0 0  fov 40  resolution 1 1
material chrome mirror albedo 1 1 1
quad -5 0 -5  -5 0 5  5 0 5  5 0 -5  material chrome
quad -2 3 -5  2 3 -5  2 3 -1  -2 3 -1  emission 1 1 1
)";

// A diffuse floor (albedo 0.5) under a point light of intensity 8 at height 2 above (1, 0, 1).
const char* kPointScene = R"(
camera eye 0 6 6  target 0 0 0  fov 40  resolution 1 1
material floor diffuse albedo 0.5 0.5 0.5
quad -5 0 -5  -5 0 5  5 0 5  5 0 -5  material floor
pointlight position 1 2 1  intensity 8 8 8
)";

}  // namespace

TEST_CASE("direct: a point light's sample carries f I cos / d^2 (Eq. 2.4) [1 pt]") {
    // From floor points x, the light at distance d under the angle theta from the normal:
    // value = (0.5 / pi) * 8 * cos(theta) / d^2 per channel, exactly (no randomness is involved).
    const ps::Scene scene = ps::parseScene(kPointScene, "point light over a floor (test_delta.cpp)");
    int failures = 0;
    for (const Vec3& target : {Vec3(1.0f, 0.0f, 1.0f), Vec3(0.0f, 0.0f, 0.0f), Vec3(-1.0f, 0.0f, 2.0f)}) {
        ps::Ray ray(scene.camera.position(), glm::normalize(target - scene.camera.position()));
        ps::SurfacePoint sp;
        REQUIRE(scene.intersect(ray, sp));
        const ps::DirectSample d = ps::sampleDirectLight(scene, sp, -ray.d, 0.5f, Vec2(0.5f));
        const glm::dvec3 toLight = glm::dvec3(1.0, 2.0, 1.0) - glm::dvec3(sp.p);
        const double d2 = glm::dot(toLight, toLight), cosTheta = toLight.y / std::sqrt(d2);
        const double expected = 0.5 / 3.14159265358979323846 * 8.0 * cosTheta / d2;
        const double got = d.value.g;
        if (!(std::abs(got - expected) <= 1e-4 * expected && d.delta) && ++failures <= 3)
            FAIL_CHECK("floor point " << str(sp.p) << " under the point light (1, 2, 1) of intensity 8, d^2 = " << d2
                                      << ": expected a delta sample of value (albedo / pi) I cos / d^2 = " << expected
                                      << ", got " << got << " (delta " << d.delta << ", ratio " << got / expected
                                      << "; d^2 = " << d2 << " or d = " << std::sqrt(d2)
                                      << " times too bright: the 1/d^2 missing?)");
    }
    CHECK_MESSAGE(failures == 0, "expected every point-light sample to be right, got " << failures << " wrong");
}

TEST_CASE(
    "direct: a BSDF sample off a mirror has light pdf 0 and MIS weight 1, so MIS sees the lamp's full radiance in it (Eq. 2.12) [1 pt]") {
    const ps::Scene scene = ps::parseScene(kMirrorScene, "mirror floor (test_delta.cpp)");
    ps::Ray ray(scene.camera.position(), glm::normalize(Vec3(0.0f) - scene.camera.position()));
    ps::SurfacePoint sp;
    REQUIRE(scene.intersect(ray, sp));
    const Vec3 wo = -ray.d;
    ps::Rng rng(ps::testseed::seed(27));
    int failures = 0;
    for (int i = 0; i < 20; ++i) {
        ps::DirectRandom u;
        u.uLight = rng.uniform();
        u.uPoint = rng.uniform2();
        u.uBSDF = rng.uniform2();
        u.uLobe = rng.uniform();
        u.uChoice = rng.uniform();
        const ps::DirectSample b = ps::sampleDirectBSDF(scene, sp, wo, u.uBSDF, u.uLobe);
        const Color multi = ps::directMultiSample(scene, sp, wo, ps::Heuristic::Power, u);
        const bool ok =
            b.delta && b.pdfLight == 0.0f && std::abs(sum(b.value) - 3.0) <= 1e-4 && std::abs(sum(multi) - 3.0) <= 1e-4;
        if (!ok && ++failures <= 3)
            FAIL_CHECK(
                "the mirror floor at "
                << str(sp.p) << " reflects the lamp of radiance 1: expected the BSDF sample "
                << "to be delta with pdfLight 0 and value (1, 1, 1), and directMultiSample (power) to be (1, 1, 1) "
                << "(weight 1); got delta " << b.delta << ", pdfLight " << b.pdfLight << ", value " << str(b.value)
                << ", directMultiSample " << str(multi) << " (ratio " << sum(multi) / 3.0
                << "; below 1: the delta sample got a light pdf, Eq. 2.12?)");
    }
    CHECK_MESSAGE(failures == 0, "expected every BSDF sample off the mirror to be right, got " << failures << " wrong");
}
