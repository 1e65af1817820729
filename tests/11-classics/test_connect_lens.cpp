// Lesson 11, graded: bidirectional path tracing's technique t = 0, connectLens (Eq. 11.16, 11.17),
// on light paths whose step to the lens is known exactly, against values computed here by hand:
//   m = 0: a point light (intensity I) whose emission direction is replayed to aim at a chosen lens
//          point: value = 4 pi I (the particle's power, P(l) = 1) times width * height * W_e;
//   m = 1: the same light's particle on a mirror turned so that its reflection goes to a chosen lens
//          point: value = beta_1 * albedo * width * height * W_e (a delta lobe keeps the power);
//   W_e = 1 / (pi r^2 A cos^4 theta) (Eq. 11.14), raster: where the ray crosses the plane of focus.
// And not valid where the step misses the lens, where something blocks it, or for a pinhole. (A
// black wall stands 1 m behind the camera: the shadow ray ends at the lens, not beyond.)
#include "lens_support.h"

using namespace lens11;

namespace {

constexpr double kPi = 3.14159265358979323846;
const LensCase kCam = {"the t = 0 test camera", Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 16, 16, 0.2f, 3.0f};
const Vec3 kLight(0.5f, 1.0f, 4.0f);
const Vec3 kMirror(0.6f, -0.5f, 2.5f);
constexpr double kIntensity = 100.0;
const Color kAlbedo(0.8f, 0.9f, 1.0f);

std::string camera(float radius) {
    return "camera eye 0 0 0  target 0 0 1  up 0 1 0  fov 40  resolution 16 16" +
           (radius > 0.0f ? "  lens " + std::to_string(radius) + "  focus 3" : std::string()) + "\n";
}
std::string vec(const DVec3& v) {
    return std::to_string(v.x) + " " + std::to_string(v.y) + " " + std::to_string(v.z) + "  ";
}

// The scene: the point light, and a mirror at kMirror turned to reflect the light towards `aim`;
// `blocker`: a black square half way between the mirror and the lens.
ps::Scene scene(float radius, const DVec3& aim, bool blocker) {
    const DVec3 M(kMirror), n = glm::normalize(glm::normalize(DVec3(kLight) - M) + glm::normalize(aim - M));
    const DVec3 t1 = glm::normalize(glm::cross(n, DVec3(0, 0, 1))), t2 = glm::cross(n, t1);
    const double a = 0.1;
    std::string text =
        camera(radius) + "material chrome mirror albedo 0.8 0.9 1\nmaterial black diffuse albedo 0 0 0\n";
    text += "pointlight position 0.5 1 4  intensity 100 100 100\n";
    text += "quad -2 -2 -1  2 -2 -1  2 2 -1  -2 2 -1  material black\n";  // a wall behind the camera
    text += "quad " + vec(M - a * t1 - a * t2) + vec(M + a * t1 - a * t2) + vec(M + a * t1 + a * t2) +
            vec(M - a * t1 + a * t2) + "material chrome\n";
    if (blocker) {
        const DVec3 c = 0.5 * (M + aim), b = glm::normalize(aim - M);
        const DVec3 s1 = glm::normalize(glm::cross(b, DVec3(0, 1, 0))), s2 = glm::cross(b, s1);
        text += "quad " + vec(c - 0.2 * s1 - 0.2 * s2) + vec(c + 0.2 * s1 - 0.2 * s2) + vec(c + 0.2 * s1 + 0.2 * s2) +
                vec(c - 0.2 * s1 + 0.2 * s2) + "material black\n";
    }
    return ps::parseScene(text, "t0-test.scene");
}

// W_e(z, w) by hand (it does not depend on z inside the image), and the raster position of the ray (z, w).
double importance(const DVec3& w) {
    const double cosT = glm::dot(w, kCam.f()), A = 4.0 * kCam.tx() * kCam.ty();
    return 1.0 / (kPi * double(kCam.radius) * kCam.radius * A * cosT * cosT * cosT * cosT);
}
Vec2 rasterOf(const DVec3& z, const DVec3& w) {
    return kCam.rasterOfFocal(z + w * (kCam.focus / glm::dot(w, kCam.f())));
}

ps::PathVertex lightVertex(const ps::Scene& s) {
    ps::PathVertex y0;
    y0.sp.p = kLight;
    y0.sp.light = 0;
    y0.onLight = true;
    y0.pointLight = true;
    y0.pdfFwd = s.lightSelectionProb(0);
    y0.beta = Color(1.0f / y0.pdfFwd);
    return y0;
}

// y_1: the mirror's centre, as the light's particle finds it, with the given beta.
ps::PathVertex mirrorVertex(const ps::Scene& s, const Color& beta) {
    ps::Ray ray(kLight, glm::normalize(kMirror - kLight));
    ps::SurfacePoint sp;
    REQUIRE_MESSAGE(s.intersect(ray, sp), "test set-up: the light's ray misses the mirror");
    ps::PathVertex v = ps::surfaceVertex(s, sp);
    v.beta = beta;
    return v;
}

void checkHit(const char* what, const ps::LensConnection& c, const DVec3& aim, const DVec3& from, const Color& want) {
    REQUIRE_MESSAGE(c.valid, what << ": expected a valid connection (its ray meets the lens at " << str(Vec3(aim))
                                  << ", radius " << num(kCam.radius) << ", nothing in between), got none");
    const DVec3 z(c.lens.sp.p), w = glm::normalize(from - aim);
    CHECK_MESSAGE(glm::length(z - aim) < 1e-4, what << ": expected the lens point " << str(Vec3(aim)) << ", got "
                                                    << str(c.lens.sp.p) << " (camera.hitLens: where the ray meets it)");
    CHECK_MESSAGE(c.lens.onCamera,
                  what << ": expected c.lens to be a lens vertex (cameraVertex(scene, z): flag onCamera)");
    const Vec2 r = rasterOf(aim, w);
    CHECK_MESSAGE(glm::length(c.raster - r) < 0.01f, what << ": expected raster " << str(r) << ", got " << str(c.raster)
                                                          << " (camera.lensRasterOfDirection(z, towards the light "
                                                             "side))");
    for (int k = 0; k < 3; ++k)
        CHECK_MESSAGE(std::abs(c.value[k] / want[k] - 1.0f) < 2e-3f,
                      what << ": channel " << k << ": expected value = beta' * width * height * W_e = " << num(want[k])
                           << ", got " << num(c.value[k])
                           << " (beta' the particle's power after the step; W_e = 1 / (pi r^2 A cos^4 theta); no "
                              "cosine or 1 / d^2 of the step: its density cancels them, Eq. 11.17)");
}

}  // namespace

TEST_CASE(
    "t = 0: connectLens from a point light and from a mirror, against values by hand (Eq. 11.16, 11.17) [2 pts]") {
    const double wh = double(kCam.w) * kCam.h;
    SUBCASE("m = 0: the light's own particle meets the lens") {
        const DVec3 aim(-0.08, 0.05, 0.0);
        const ps::Scene s = scene(kCam.radius, DVec3(0.05, -0.03, 0.0), false);
        const Vec2 uDir = ps::invertUniformSphere(Vec3(glm::normalize(aim - DVec3(kLight))));
        // startLightPath(rng.uniform(), rng.uniform2(), rng.uniform2()): C++ may evaluate the three
        // arguments in either order; with one light and a point light only uDir matters, and it is
        // (ux, uy) either way.
        Replay numbers({uDir.x, uDir.y, 0.5f, uDir.x, uDir.y});
        ps::Rng rng(1, 1);
        rng.replayFrom(&numbers);
        const ps::PathVertex y0 = lightVertex(s);
        const ps::LensConnection c = ps::connectLens(s, &y0, 0, rng);
        const DVec3 w = glm::normalize(DVec3(kLight) - aim);
        checkHit("m = 0 (the point light straight into the lens)", c, aim, DVec3(kLight),
                 Color(float(4.0 * kPi * kIntensity * wh * importance(w))));
        CHECK_MESSAGE(numbers.read == 5,
                      "m = 0: expected startLightPath's five numbers to be drawn, got " << numbers.read);
        CHECK_MESSAGE((c.light.pointLight && c.light.onLight && glm::length(c.light.sp.p - kLight) < 1e-5f),
                      "m = 0: expected c.light to be the new light vertex: the point light at "
                          << str(kLight) << " (onLight, pointLight), got one at " << str(c.light.sp.p));
    }
    SUBCASE("m = 1: the particle on the mirror reflects into the lens") {
        const DVec3 aim(0.05, -0.03, 0.0);
        const ps::Scene s = scene(kCam.radius, aim, false);
        const Color beta(0.3f, 0.5f, 0.7f);
        const ps::Path y = {lightVertex(s), mirrorVertex(s, beta)};
        Replay numbers({0.3f, 0.6f, 0.2f});
        ps::Rng rng(1, 2);
        rng.replayFrom(&numbers);
        const ps::LensConnection c = ps::connectLens(s, y.data(), 1, rng);
        const DVec3 w = glm::normalize(DVec3(kMirror) - aim);
        const double We = wh * importance(w);
        checkHit("m = 1 (light -> mirror -> lens)", c, aim, DVec3(kMirror),
                 Color(float(beta.r * kAlbedo.r * We), float(beta.g * kAlbedo.g * We), float(beta.b * kAlbedo.b * We)));
    }
    SUBCASE("not valid: a step that misses the lens, a blocked step, a pinhole camera") {
        const Color beta(1.0f);
        const auto attempt = [&](const ps::Scene& s) {
            const ps::Path y = {lightVertex(s), mirrorVertex(s, beta)};
            Replay numbers({0.3f, 0.6f, 0.2f});
            ps::Rng rng(1, 3);
            rng.replayFrom(&numbers);
            return ps::connectLens(s, y.data(), 1, rng);
        };
        const ps::LensConnection miss = attempt(scene(kCam.radius, DVec3(0.21, 0.05, 0.0), false));
        CHECK_MESSAGE(!miss.valid,
                      "the mirror's reflection passes 0.215 from the lens centre (radius 0.2): expected "
                      "no connection, got value "
                          << str(miss.value));
        const ps::LensConnection blocked = attempt(scene(kCam.radius, DVec3(0.05, -0.03, 0.0), true));
        CHECK_MESSAGE(!blocked.valid,
                      "a black square between the mirror and the lens: expected no connection (the "
                      "ray up to the lens is a shadow ray), got value "
                          << str(blocked.value));
        const ps::LensConnection pinhole = attempt(scene(0.0f, DVec3(0.0, 0.0, 0.0), false));
        CHECK_MESSAGE(!pinhole.valid, "a pinhole camera: expected no connection (no ray hits a pinhole), got value "
                                          << str(pinhole.value));
    }
}
