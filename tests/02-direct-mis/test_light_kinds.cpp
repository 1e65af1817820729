// Lesson 2, graded: direct illumination from every kind of light in one scene (issue 28,
// "reach": the lesson's other scenes have area lights, or a point light alone, never a
// background). A diffuse floor under a background, a point light and a square lamp: every light
// sample (a grid of the numbers) against the value the test computes from the framework's own
// light choice, BSDF and the densities of Eq. 2.4 by hand (a background direction has the density
// 1 / (4 pi) times the light's selection probability; a point light none: delta); a BSDF sample
// that leaves the scene sees the background, or nothing in a scene without one; no light at all
// gives nothing. Exact, no statistics.
#include <cmath>
#include "lesson02.h"

using namespace lesson02;

namespace {

constexpr double kPi = 3.14159265358979323846;

// (The background dim enough that light selection by power picks every light in the grid.)
const char* kLights = R"(
camera eye 0 6 6  target 0 0 0  fov 40  resolution 1 1
material floor diffuse albedo 0.6 0.6 0.6
quad -5 0 -5  -5 0 5  5 0 5  5 0 -5  material floor
pointlight position 1 2 1  intensity 8 6 4
quad -0.5 3 -0.5  0.5 3 -0.5  0.5 3 0.5  -0.5 3 0.5  emission 5 5 5
background radiance 0.005 0.01 0.015
)";

bool close(const Color& a, const Color& b) { return glm::length(a - b) <= 1e-4f * (glm::length(b) + 1e-6f); }

ps::SurfacePoint floorAt(const ps::Scene& scene, float x, float z) {
    ps::Ray r(Vec3(x, 1.0f, z), Vec3(0, -1, 0));
    ps::SurfacePoint sp;
    REQUIRE(scene.intersect(r, sp));
    return sp;
}

}  // namespace

TEST_CASE("direct light: a background, a point light and a lamp in one scene (Eq. 2.4, 2.5) [1 pt]") {
    const ps::Scene scene = ps::parseScene(kLights, "light-kinds.scene");
    REQUIRE(scene.background >= 0);
    const ps::SurfacePoint sp = floorAt(scene, 0.3f, -0.2f);
    const ps::Material& m = scene.materials[size_t(sp.material)];
    const Vec3 wo = glm::normalize(Vec3(0.2f, 1.0f, 0.5f));
    int kinds[3] = {0, 0, 0};
    for (int i = 0; i < 24; ++i)
        for (int j = 0; j < 6; ++j) {
            const float uLight = (float(i) + 0.5f) / 24.0f;
            const Vec2 uPoint((float(j) + 0.5f) / 6.0f, (float(j) * 5.0f + 0.37f) / 30.0f);
            float select = 0.0f;
            const int l = scene.selectLight(uLight, select);
            REQUIRE(l >= 0);
            const ps::Light& light = scene.lights[size_t(l)];
            const ps::DirectSample d = ps::sampleDirectLight(scene, sp, wo, uLight, uPoint);
            if (light.kind == ps::LightKind::Area) {
                ++kinds[0];
                continue;  // the area light's samples: test_direct.cpp
            }
            Color want(0.0f);
            float pdf = 0.0f;
            std::string what;
            if (light.kind == ps::LightKind::Background) {
                ++kinds[1];
                what = "the background";
                pdf = float(select / (4.0 * kPi));
                const Vec3 wi = d.wi;
                ps::Ray shadow = scene.spawnRay(sp, wi);
                const bool blocked = scene.occluded(shadow);
                if (!blocked)
                    want = ps::evalBSDF(m, sp.n, wo, wi) * scene.backgroundRadiance() *
                           (std::abs(glm::dot(sp.n, wi)) / pdf);
                CHECK_MESSAGE(std::abs(glm::length(wi) - 1.0f) < 1e-5f, what << ": expected a unit direction");
            } else {
                ++kinds[2];
                what = "the point light";
                pdf = select;
                const Vec3 toLight = light.position - sp.p;
                const float d2 = glm::dot(toLight, toLight);
                const Vec3 wi = toLight / std::sqrt(d2);
                want = ps::evalBSDF(m, sp.n, wo, wi) * light.Le * (std::abs(glm::dot(sp.n, wi)) / d2 / select);
                CHECK_MESSAGE(d.delta, what << ": expected a delta sample");
            }
            CHECK_MESSAGE(std::abs(d.pdfLight - pdf) <= 1e-5f * pdf,
                          what << " (uLight " << uLight << ", selection probability " << select
                               << "): expected pdfLight " << pdf << ", got " << d.pdfLight);
            CHECK_MESSAGE(close(d.value, want), what << " (uLight " << uLight << ", uPoint " << str(Vec3(uPoint, 0))
                                                     << "): expected f Le |cos| / pdf = " << str(want) << ", got "
                                                     << str(d.value));
        }
    REQUIRE_MESSAGE((kinds[0] > 0 && kinds[1] > 0 && kinds[2] > 0), "the test's own layout: every light chosen");
    // The densities pdfLightDirection gives MIS for a direction found by BSDF sampling.
    const int bg = scene.background;
    const float bgPdf = ps::pdfLightDirection(scene, bg, sp.p, sp.p + Vec3(0, 1, 0), Vec3(0, -1, 0));
    const double wantBg = double(scene.lightSelectionProb(bg)) / (4.0 * kPi);
    CHECK_MESSAGE(std::abs(bgPdf - wantBg) <= 1e-5 * wantBg,
                  "pdfLightDirection of the background: expected its selection probability / (4 pi) = "
                      << wantBg << ", got " << bgPdf);
    for (size_t l = 0; l < scene.lights.size(); ++l)
        if (scene.lights[l].kind == ps::LightKind::Point)
            CHECK_MESSAGE(ps::pdfLightDirection(scene, int(l), sp.p, scene.lights[l].position, Vec3(0, 1, 0)) == 0.0f,
                          "pdfLightDirection of a point light: expected 0 (no direction samples it)");
    // A BSDF sample straight up (the middle of the numbers' square), away from the lamp, leaves
    // the scene: the background, with its density for MIS.
    const ps::DirectSample up = ps::sampleDirectBSDF(scene, floorAt(scene, 2.5f, 2.5f), wo, Vec2(0.5f), 0.5f);
    REQUIRE(up.wi.y > 0.9f);
    CHECK_MESSAGE(close(up.value, Color(0.6f) * scene.backgroundRadiance()),
                  "sampleDirectBSDF leaving the scene under a background: expected the weight (albedo 0.6) times its "
                  "radiance, got "
                      << str(up.value));
    CHECK_MESSAGE(std::abs(up.pdfLight - float(wantBg)) <= 1e-5f * float(wantBg),
                  "sampleDirectBSDF leaving the scene: expected pdfLight = the background's density "
                      << wantBg << ", got " << up.pdfLight);
    // Without a background a ray that leaves the scene finds nothing; without any light, nothing.
    const ps::Scene dark = ps::parseScene(R"(
camera eye 0 6 6  target 0 0 0  fov 40  resolution 1 1
material floor diffuse albedo 0.6 0.6 0.6
quad -5 0 -5  -5 0 5  5 0 5  5 0 -5  material floor
)",
                                          "no-light.scene");
    const ps::SurfacePoint spDark = floorAt(dark, 0.3f, -0.2f);
    const ps::DirectSample none = ps::sampleDirectBSDF(dark, spDark, wo, Vec2(0.5f), 0.5f);
    CHECK_MESSAGE((ps::isBlack(none.value) && none.pdfLight == 0.0f),
                  "sampleDirectBSDF leaving a scene without a background: expected nothing");
    const ps::DirectSample noLight = ps::sampleDirectLight(dark, spDark, wo, 0.5f, Vec2(0.5f));
    CHECK_MESSAGE(ps::isBlack(noLight.value), "sampleDirectLight in a scene without light: expected black");
}
