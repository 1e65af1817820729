// Lesson 11, graded: what the lesson's other scenes never show its pieces (issue 28, "reach"):
//  - whittedDirect at a quad lit and seen from its back (two-sided diffuse: I |cos| / d^2 albedo /
//    pi, computed here in double);
//  - drt through glass: a lamp behind a glass ball (the two eta^2 cancel) and a lamp inside one
//    (they do not), against the test's own trace of the specular bounces with the framework's
//    sampleBSDF and the same numbers (every uniform number 0.5 or 0.01, replayed);
//  - the t = 0 connection of a light path that starts on the background (connectLens, m = 0),
//    against the test's replay of the light path and W_e by hand.
#include "11-classics/distributed.h"
#include "lens_support.h"
#include "paths_support.h"

namespace {

using ps::Color;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;

struct Constant : ps::UniformSource {
    float fill = 0.5f;
    float next() override { return fill; }
};

bool close(const Color& a, const Color& b, double rel = 2e-5) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(double(a[c]) - double(b[c])) > rel * std::max(1e-12, std::abs(double(b[c])))) return false;
    return true;
}

using ps::testrender::specularOracle;  // tests/support/render_helpers.h

}  // namespace

TEST_CASE("whittedDirect: a quad lit and seen from its back: I |cos| / d^2 albedo / pi, exactly [1 pt]") {
    // A diffuse floor (y = 0, normal +y, albedo 0.6) with a point light 2 below it: the floor's
    // back is lit, and seen from below. Diffuse surfaces are two-sided: the cosine is |n . w|.
    const ps::Scene scene = ps::parseScene(
        "camera eye 0 -3 -6  target 0 0 0  fov 45  resolution 8 8\n"
        "material floor diffuse albedo 0.6 0.6 0.6\n"
        "quad -50 0 -50  -50 0 50  50 0 50  50 0 -50  material floor\n"
        "pointlight position 0 -2 0  intensity 5 4 3\n",
        "back-lit-floor.scene");
    const float xs[][2] = {{0, 0}, {1, 0}, {0.5f, -1.5f}, {-3, 2}};
    for (const auto& q : xs) {
        ps::Ray r(Vec3(q[0], -1.0f, q[1]), Vec3(0, 1, 0));
        ps::SurfacePoint sp;
        REQUIRE(scene.intersect(r, sp));
        REQUIRE(sp.n.y > 0.0f);  // the test's own layout: the normal points away from the light
        const Vec3 wo = glm::normalize(Vec3(0.3f, -1, -0.4f));
        const double d2 = double(q[0]) * q[0] + double(q[1]) * q[1] + 4.0,
                     f = 0.6 / 3.14159265358979 * 2.0 / std::sqrt(d2) / d2;
        const Color want(float(5 * f), float(4 * f), float(3 * f));
        const Color got = ps::whittedDirect(scene, sp, wo);
        CHECK_MESSAGE(close(got, want), "the floor's back at (" << q[0] << ", 0, " << q[1]
                                                                << "), light 2 below, seen from below: expected I "
                                                                   "|cos| / d^2 * albedo / pi = "
                                                                << str(want) << ", got " << str(got)
                                                                << " (a diffuse surface reflects on both sides)");
    }
}

TEST_CASE("drt: a lamp behind a glass ball and a lamp inside one, exactly (Eq. 11.19) [1 pt]") {
    // A glass ball (ior 1.5) at (0, 0, -4) in front of a lamp at z = -6; a second glass ball at
    // (4, 0, -4) around a small emitting ball. The camera's rays go through the balls' centres
    // (normal incidence at every surface): with every number 0.5 they refract, with 0.01 they
    // reflect at the first surface and leave the scene (the background).
    const ps::Scene scene = ps::parseScene(
        "camera eye 0 0 0  target 0 0 -1  fov 40  resolution 4 4\n"
        "material glass dielectric ior 1.5\n"
        "sphere center 0 0 -4  radius 1  material glass\n"
        "quad -1 -1 -6  1 -1 -6  1 1 -6  -1 1 -6  emission 2 3 4\n"
        "sphere center 4 0 -4  radius 1  material glass\n"
        "sphere center 4 0 -4  radius 0.3  emission 5 4 3\n"
        "background radiance 0.25 0.5 0.75\n",
        "glass-lamps.scene");
    struct View {
        Vec3 d;
        const char* what;
    };
    const View views[] = {{Vec3(0, 0, -1), "a lamp behind a glass ball (the eta^2 of entering and leaving cancel)"},
                          {glm::normalize(Vec3(4, 0, -4)),
                           "a lamp inside a glass ball (the light leaves the glass once: its eta^2 stays)"}};
    // maxdepth 8, and 1: the lamp behind the ball is then out of reach (the ball's far side is the
    // second vertex), the lamp inside it is the second vertex and still seen.
    for (const View& v : views)
        for (const float u : {0.5f, 0.01f})
            for (const int maxDepth : {8, 1}) {
                const ps::Ray ray(Vec3(0.0f), v.d);
                bool lamp = false;
                const Color want = specularOracle(scene, ray, u, maxDepth, lamp);
                if (u == 0.5f && maxDepth == 8) REQUIRE_MESSAGE(lamp, "the test's own layout: " << v.what);
                Constant numbers;
                numbers.fill = u;
                ps::Rng rng;
                rng.replayFrom(&numbers);
                const Color got = ps::LiDistributed(scene, ray, rng, maxDepth);
                CHECK_MESSAGE(close(got, want, 1e-4), "LiDistributed, maxdepth "
                                                          << maxDepth << ", " << v.what << " (every uniform number "
                                                          << u << "): expected " << str(want)
                                                          << " (the emission times the glass's sample "
                                                             "weights in radiance transport), got "
                                                          << str(got));
            }
}

TEST_CASE("connectLens: a light path from the background to the lens (t = 0, m = 0, Eq. 11.16, 11.17) [1 pt]") {
    // The lens camera of test_connect_lens.cpp (radius 0.2, focus 3, looking down +z) under a
    // constant background Lb, the only light; a black wall behind the camera gives the scene its
    // extent (bounding radius R). connectLens with m = 0 starts a fresh light path from the
    // background (lesson 5's startLightPath: a point y0 on the disc of radius R across the scene,
    // a uniform direction, power beta = Lb 4 pi^2 R^2, the background's power over P(l) = 1).
    // Where its ray meets the lens at z, expected: the new light vertex on the background (onLight,
    // infinite, its normal pointing back to the background: from z towards y0), z on the lens disc,
    // and value = beta * width * height * W_e(z -> y0) with W_e = 1 / (pi r^2 A cos^4 theta) by hand.
    const lens11::LensCase cam = {
        "the background test camera", Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 16, 16, 0.2f, 3.0f};
    const ps::Scene scene = ps::parseScene(
        "camera eye 0 0 0  target 0 0 1  up 0 1 0  fov 40  resolution 16 16  lens 0.2  focus 3\n"
        "material black diffuse albedo 0 0 0\n"
        "quad -0.6 -0.6 -0.3  0.6 -0.6 -0.3  0.6 0.6 -0.3  -0.6 0.6 -0.3  material black\n"
        "background radiance 0.5 0.6 0.7\n",
        "lens-background.scene");
    REQUIRE(scene.background >= 0);
    const double Lb[3] = {0.5, 0.6, 0.7}, R = double(scene.radius), kPi = 3.14159265358979323846;
    ps::Rng rng(ps::testseed::seed(1131));
    int valid = 0, tries = 0;
    for (; tries < 200000 && valid < 20; ++tries) {
        const ps::LensConnection c = ps::connectLens(scene, nullptr, 0, rng);
        if (!c.valid) continue;
        ++valid;
        CHECK_MESSAGE((c.light.onLight && c.light.infinite && !c.light.pointLight),
                      "connectLens, m = 0, the background's light path: expected c.light on the light, infinite, not a "
                      "point light");
        const lens11::DVec3 z(c.lens.sp.p), y0(c.light.sp.p), back = glm::normalize(y0 - z);
        CHECK_MESSAGE(
            (std::abs(z.z) < 1e-5 && z.x * z.x + z.y * z.y <= 0.04 * (1.0 + 1e-4)),
            "connectLens: expected the lens point on the lens disc (z = 0, radius 0.2), got " << str(c.lens.sp.p));
        CHECK_MESSAGE(glm::length(lens11::DVec3(c.light.sp.n) - back) < 1e-4,
                      "connectLens, m = 0, the background's light path from "
                          << str(c.light.sp.p) << " to the lens at " << str(c.lens.sp.p)
                          << ": expected the light vertex's normal " << str(Vec3(back))
                          << " (back towards the background, where "
                             "the path comes from), got "
                          << str(c.light.sp.n));
        const double cosT = glm::dot(back, cam.f()), A = 4.0 * cam.tx() * cam.ty();
        const double We = 1.0 / (kPi * double(cam.radius) * cam.radius * A * cosT * cosT * cosT * cosT);
        for (int k = 0; k < 3; ++k) {
            const double want = Lb[k] * 4.0 * kPi * kPi * R * R * 16.0 * 16.0 * We;
            CHECK_MESSAGE(std::abs(double(c.value[k]) / want - 1.0) < 2e-3,
                          "connectLens, m = 0 from the background, channel "
                              << k << ": expected value = beta * width * height * W_e = " << num(want)
                              << " (beta = Lb 4 pi^2 R^2, the background's power), got " << num(c.value[k]));
        }
    }
    // Directions the lens does not image: from behind it, and outside the image.
    const ps::ThinLens camera = cam.camera();
    CHECK_MESSAGE(camera.lensPdfDirection(Vec3(0.1f, 0, 0), Vec3(0, 0, -1)) == 0.0f,
                  "lensPdfDirection of a direction behind the lens: expected 0");
    CHECK_MESSAGE(camera.lensPdfDirection(Vec3(0.1f, 0, 0), glm::normalize(Vec3(1, 0, 0.2f))) == 0.0f,
                  "lensPdfDirection of a direction far outside the image: expected 0");
    // No light: no light path starts.
    const ps::Scene dark = ps::parseScene(
        "camera eye 0 0 0  target 0 0 1  up 0 1 0  fov 40  resolution 16 16  lens 0.2  focus 3\n"
        "material black diffuse albedo 0 0 0\n"
        "quad -0.6 -0.6 -0.3  0.6 -0.6 -0.3  0.6 0.6 -0.3  -0.6 0.6 -0.3  material black\n",
        "lens-dark.scene");
    CHECK_MESSAGE(!ps::connectLens(dark, nullptr, 0, rng).valid,
                  "connectLens, m = 0, in a scene without light: "
                  "expected no connection");
    CHECK_MESSAGE(valid >= 20,
                  "connectLens, m = 0, under a background alone: expected light paths that meet the lens "
                  "(about 1 in 100 here), got "
                      << valid << " of " << tries);
}

TEST_CASE("pt through your lens rays: a plane in focus looks as through the pinhole (z-test) [1 pt]") {
    // An oracle independent of the lens code: a Lambertian plane exactly at the focus distance, a
    // checkerboard of two albedos under a point light. Every ray through a pixel's point of focus
    // meets the plane there whatever lens point it leaves from, and a Lambertian surface sends the
    // same radiance every way: the lens image equals the pinhole's (the framework's camera, lessons
    // 0 and 3), pixel by pixel. Rays not through the point of focus, or a sphere of focus instead of
    // the plane (sharp on the axis, a blur that grows towards the corners: a wide field of view and
    // a large lens here), blur or move the squares' edges. Per-pixel z-test at alpha()
    // (lens_support.h: the Sidak level over the 432 channels, at least 99.75 % pass).
    std::string planes = "material a diffuse albedo 0.8 0.8 0.8\nmaterial b diffuse albedo 0.1 0.2 0.4\n";
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            const double x0 = -3.3 + 1.1 * i, y0 = -3.3 + 1.1 * j, x1 = x0 + 1.1, y1 = y0 + 1.1;
            const std::string z = " -4  ";
            planes += "quad " + num(x0) + " " + num(y0) + z + num(x1) + " " + num(y0) + z + num(x1) + " " + num(y1) +
                      z + num(x0) + " " + num(y1) + z + "material " + ((i + j) % 2 ? "a" : "b") + "\n";
        }
    planes += "pointlight position 0 0 -1  intensity 6 6 6\nrender maxdepth 1\n";
    const ps::Scene lens = ps::parseScene(
        "camera eye 0 0 0  target 0 0 -1  fov 70  resolution 12 12  lens 1  focus 4\n" + planes, "lens-plane.scene");
    const ps::Scene pinhole =
        ps::parseScene("camera eye 0 0 0  target 0 0 -1  fov 70  resolution 12 12\n" + planes, "pinhole-plane.scene");
    const ps::testrender::Render a = ps::testrender::render(lens, "pt", 256, ps::testseed::seed(1132));
    const ps::testrender::Render b = ps::testrender::render(pinhole, "pt", 256, ps::testseed::seed(1133));
    REQUIRE_MESSAGE(ps::testrender::total(a.mean) > 0.0, "pt through the lens renders the lit plane black");
    const ps::stats::ZTestResult z = ps::stats::zTestImages(a.mean, a.variance, b.mean, b.variance, lens11::alpha());
    CHECK_MESSAGE(z.passed,
                  "pt through the lens (a) against the pinhole (b), a plane at the focus distance (12 x 12, "
                  "256 spp; image totals "
                      << num(ps::testrender::total(a.mean)) << " and " << num(ps::testrender::total(b.mean)) << "):\n  "
                      << z.report
                      << "\n  every lens ray through a pixel must pass through the pinhole ray's point on "
                         "the plane of focus (distance F along the forward axis, Eq. 11.12)");
}
