// Lesson 7, graded: the four kinds of connection of Eq. 7.4, each alone, on vertices the test
// builds itself (hits of rays it shoots, with throughputs beta of its own choosing, a different
// colour per vertex so a missing or doubled beta shows), against an independent value:
//   connectEmitter (s = 0)     the emission written in the scene file, beta_z Le (Lambertian
//                              emitters: the same radiance in every direction of the front side);
//   connectCamera (t = 1)      lesson 5's connectToCamera times f = albedo / pi (or Le, or a point
//                              light's intensity);
//   connectLight (s = 1)       lesson 2's sampleDirectLight with the same random numbers (light
//                              sampling, Eq. 2.4: f Le |cos| / p_omega is the same number as
//                              f Le G / p_A), in a scene with an area light, a point light and a
//                              background, so the light-selection probability matters;
//   connectVertices (s, t >= 2) beta albedo/pi cos cos / d^2 albedo/pi beta, computed here from
//                              the positions and normals.
// Exact up to float rounding: relative 1e-4. Lessons 2 and 5 are the reference's when the grader
// builds lesson 7 alone (in a local build with your own lessons 2 and 5, run their tests first).
#include "lesson07.h"
#include "02-direct-mis/direct.h"
#include "seed.h"

using namespace lesson07;

namespace {

// A floor (normal up), a green wall at x = -2 (normal +x), a ceiling at y = 3 (normal down), an
// area light 1 x 1 at y = 2 facing down, a point light, a background, a mirror sphere on the
// floor, and a small grey blocker between the wall and the floor point (1, 0, 0.5).
const char* kScene = R"(
camera eye 0 1 -5  target 0 1 0  up 0 1 0  fov 60  resolution 16 16
material floor   diffuse albedo 0.5 0.4 0.3
material wall    diffuse albedo 0.2 0.6 0.4
material ceiling diffuse albedo 0.7 0.7 0.7
material blocker diffuse albedo 0.3 0.3 0.3
material chrome  mirror albedo 0.9 0.9 0.9
quad 3 0 -3  -3 0 -3  -3 0 3  3 0 3                    material floor
quad -2 0 -3  -2 0 3  -2 3 3  -2 3 -3                  material wall
quad 3 3 -3  3 3 3  -3 3 3  -3 3 -3                    material ceiling
quad 0.5 2 -0.5  0.5 2 0.5  -0.5 2 0.5  -0.5 2 -0.5    emission 4 3 2
quad -1 0.2 1.5  -1 0.2 2.5  -1 1.2 2.5  -1 1.2 1.5    material blocker
pointlight position 1.2 1.5 -0.5  intensity 6 5 4
background radiance 0.05 0.06 0.08
sphere center 1.5 0.5 1.5  radius 0.5  material chrome
render maxdepth 4
)";

constexpr double kRel = 1e-4;
constexpr float kPi = 3.14159265358979f;
const Color kFloor(0.5f, 0.4f, 0.3f), kWall(0.2f, 0.6f, 0.4f), kLe(4.0f, 3.0f, 2.0f);

const ps::Scene& scene() {
    static const ps::Scene s = ps::parseScene(kScene, "connect test scene");
    return s;
}

// The vertex a ray from o towards `to` hits first (the test fails if it hits nothing).
PathVertex hit(const Vec3& o, const Vec3& to, const Color& beta) {
    ps::SurfacePoint sp;
    const Vec3 d = glm::normalize(to - o);
    ps::Ray ray(o + 1e-3f * d, d);  // o may lie on a surface: start just off it
    const bool ok = scene().intersect(ray, sp);
    REQUIRE_MESSAGE(ok, "test setup: the ray from " << str(o) << " towards " << str(to) << " hits nothing");
    PathVertex v = ps::surfaceVertex(scene(), sp);
    v.beta = beta;
    return v;
}

PathVertex camera() {
    PathVertex v = ps::cameraVertex(scene());
    v.beta = Color(1.0f);
    return v;
}

int lightOfKind(ps::LightKind kind) {
    for (size_t l = 0; l < scene().lights.size(); ++l)
        if (scene().lights[l].kind == kind) return int(l);
    FAIL("test setup: no light of the kind asked");
    return -1;
}

bool close(const Color& a, const Color& b) {
    for (int c = 0; c < 3; ++c)
        if (!(std::abs(double(a[c]) - double(b[c])) <= kRel * std::abs(double(b[c])) + 1e-12)) return false;
    return true;
}

std::string ratio(const Color& got, const Color& expected) {
    std::ostringstream o;
    o << "(ratio got / expected per channel: ";
    for (int c = 0; c < 3; ++c)
        o << (c ? ", " : "") << (expected[c] != 0.0f ? num(double(got[c]) / double(expected[c]), 5) : std::string("-"));
    o << ")";
    return o.str();
}

double cosAt(const PathVertex& v, const Vec3& towards) {
    return std::abs(glm::dot(v.sp.n, glm::normalize(towards - v.sp.p)));
}

}  // namespace

TEST_CASE(
    "connectEmitter (s = 0): beta times the emission the camera subpath's last vertex sends back, front side only [1 pt]") {
    const PathVertex z0 = camera();
    const PathVertex z1 = hit(z0.p(), Vec3(0.2f, 0.0f, 0.3f), Color(0.7f, 1.3f, 0.9f));
    // Front side: from the floor up into the light.
    const Color beta(0.5f, 0.25f, 2.0f);
    const PathVertex z2 = hit(z1.p(), Vec3(0.1f, 2.0f, -0.2f), beta);
    REQUIRE(z2.onLight);
    {
        const PathVertex z[] = {z0, z1, z2};
        const ps::Connection c = ps::connectEmitter(scene(), z, 3);
        const Color expected = beta * kLe;
        CHECK_MESSAGE((c.valid && close(c.value, expected)),
                      "z_2 on the front of the area light (emission 4 3 2), beta_2 = "
                          << str(beta) << ": expected valid, C* = beta Le = " << str(expected)
                          << ", got valid = " << c.valid << ", " << str(c.value) << " " << ratio(c.value, expected)
                          << ". C* = beta_{t-1} Le(z_{t-1} -> z_{t-2}) (Eq. 7.4): is beta missing?");
    }
    // Back side: from the ceiling down onto the light's back.
    const PathVertex c1 = hit(z0.p(), Vec3(0.0f, 3.0f, 0.8f), Color(1.0f));
    const PathVertex back = hit(c1.p(), Vec3(0.1f, 0.0f, -0.8f), beta);
    REQUIRE_MESSAGE(back.onLight, "test setup: c1 " << str(c1.p()) << " back " << str(back.p()));
    {
        const PathVertex z[] = {z0, c1, back};
        const ps::Connection c = ps::connectEmitter(scene(), z, 3);
        CHECK_MESSAGE(
            !c.valid,
            "z_2 on the BACK of the area light (seen from the ceiling above it): expected no contribution, got "
                << str(c.value)
                << ". The emitted direction is from z_{t-1} towards z_{t-2}, not the direction the walk arrived in");
    }
    // The background: a vertex at infinity.
    {
        const Vec3 up = glm::normalize(Vec3(0.3f, 1.0f, 0.2f));
        PathVertex zb = ps::backgroundVertex(scene(), up);
        zb.beta = beta;
        const PathVertex z[] = {z0, z1, zb};
        const ps::Connection c = ps::connectEmitter(scene(), z, 3);
        const Color expected = beta * Color(0.05f, 0.06f, 0.08f);
        CHECK_MESSAGE((c.valid && close(c.value, expected)),
                      "z_2 at infinity (background 0.05 0.06 0.08): expected C* = "
                          << str(expected) << ", got valid = " << c.valid << ", " << str(c.value) << " "
                          << ratio(c.value, expected));
    }
    // A vertex that does not emit.
    {
        const PathVertex z[] = {z0, z1};
        const ps::Connection c = ps::connectEmitter(scene(), z, 2);
        CHECK_MESSAGE(!c.valid, "z_1 on the (non-emitting) floor: expected no contribution, got " << str(c.value));
    }
}

TEST_CASE(
    "connectCamera (t = 1): lesson 5's connection to the pinhole times f, or the light's own emission, no cosine at a point light [2 pts]") {
    const PathVertex z0 = camera();
    const Color betaLight(3.0f, 2.5f, 2.0f), beta(0.5f, 1.5f, 0.8f);
    // s = 2: the floor point (0.3, 0, 0.5), lit from the area light.
    const PathVertex y0 = hit(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 2.0f, 0.1f), betaLight);  // from below: the front
    const PathVertex y1 = hit(z0.p(), Vec3(0.3f, 0.0f, 0.5f), beta);
    REQUIRE(y0.onLight);
    {
        const PathVertex y[] = {y0, y1};
        const ps::Connection c = ps::connectCamera(scene(), y, 2);
        const ps::CameraConnection cc = ps::connectToCamera(scene(), y1.sp, true);
        REQUIRE(cc.valid);
        const Color expected = beta * (kFloor / kPi) * cc.importance;
        CHECK_MESSAGE((c.valid && close(c.value, expected)),
                      "s = 2, y_1 on the floor (albedo 0.5 0.4 0.3), beta_1 = "
                          << str(beta) << ": expected C* = beta (albedo / pi) importance = " << str(expected)
                          << ", got valid = " << c.valid << ", " << str(c.value) << " " << ratio(c.value, expected)
                          << ". Missing beta, f or connectToCamera's importance (Eq. 7.4)?");
        CHECK_MESSAGE(glm::length(c.raster - cc.raster) < 1e-4f,
                      "s = 2: expected c.raster = connectToCamera's "
                          << str(cc.raster) << " (where the point lands), got " << str(c.raster));
    }
    // s = 1 on the area light, seen from below by the camera.
    {
        const PathVertex y[] = {y0};
        const ps::Connection c = ps::connectCamera(scene(), y, 1);
        const ps::CameraConnection cc = ps::connectToCamera(scene(), y0.sp, true);
        REQUIRE(cc.valid);
        const Color expected = betaLight * kLe * cc.importance;
        CHECK_MESSAGE((c.valid && close(c.value, expected)),
                      "s = 1, y_0 on the area light (emission 4 3 2), beta_0 = "
                          << str(betaLight) << ": expected C* = beta Le importance = " << str(expected)
                          << ", got valid = " << c.valid << ", " << str(c.value) << " " << ratio(c.value, expected)
                          << ". For s = 1, f is the light's emission towards the camera");
    }
    // s = 1 at the point light: its intensity, and no cosine at the light (it has no surface).
    {
        const int l = lightOfKind(ps::LightKind::Point);
        PathVertex yp;
        yp.sp.p = scene().lights[size_t(l)].position;
        yp.sp.n = glm::normalize(Vec3(0.3f, -1.0f, 0.2f));  // meaningless at a point: must not count
        yp.sp.light = l;
        yp.onLight = yp.pointLight = true;
        yp.beta = betaLight;
        const PathVertex y[] = {yp};
        const ps::Connection c = ps::connectCamera(scene(), y, 1);
        const ps::CameraConnection cc = ps::connectToCamera(scene(), yp.sp, false);
        REQUIRE(cc.valid);
        const Color expected = betaLight * Color(6.0f, 5.0f, 4.0f) * cc.importance;
        CHECK_MESSAGE(
            (c.valid && close(c.value, expected)),
            "s = 1 at the point light (intensity 6 5 4): expected C* = beta I importance = "
                << str(expected) << ", got valid = " << c.valid << ", " << str(c.value) << " "
                << ratio(c.value, expected)
                << ". A point light has no surface: connectToCamera(..., onSurface = false), no |cos theta_y|");
    }
    // A background y_0 cannot be joined to the pinhole; a point behind the blocker is not seen.
    {
        PathVertex yb = ps::backgroundVertex(scene(), glm::normalize(Vec3(0.0f, 1.0f, -1.0f)));
        yb.beta = betaLight;
        const PathVertex y[] = {yb};
        const ps::Connection c = ps::connectCamera(scene(), y, 1);
        CHECK_MESSAGE(!c.valid,
                      "s = 1 with y_0 at infinity (the background): a direction cannot be joined to the pinhole "
                      "(Eq. 7.12); expected no contribution, got "
                          << str(c.value));
    }
    {
        const PathVertex yHidden =
            hit(Vec3(1.5f, 2.9f, 2.05f), Vec3(1.5f, 0.0f, 2.05f), beta);  // the floor behind the sphere
        const PathVertex y[] = {y0, yHidden};
        REQUIRE(!ps::connectToCamera(scene(), yHidden.sp, true).valid);
        const ps::Connection c = ps::connectCamera(scene(), y, 2);
        CHECK_MESSAGE(!c.valid,
                      "s = 2 with y_1 on the floor behind the mirror sphere: the camera cannot see it; expected no "
                      "contribution, got "
                          << str(c.value));
    }
}

TEST_CASE(
    "connectLight (s = 1): lesson 2's light sample, with the light-selection probability, from an area light, a point light and the background [2 pts]") {
    const PathVertex z0 = camera();
    const Color beta(0.6f, 1.2f, 0.9f);
    const int area = lightOfKind(ps::LightKind::Area), point = lightOfKind(ps::LightKind::Point),
              bg = lightOfKind(ps::LightKind::Background);
    int checked = 0, seen[3] = {0, 0, 0}, blocked = 0, wrongValue = 0;  // the first 3 wrong values are shown
    for (const Vec3& target : {Vec3(0.3f, 0.0f, 0.5f), Vec3(-0.8f, 0.0f, 1.6f), Vec3(-2.0f, 0.9f, 1.0f)}) {
        const PathVertex z1 = hit(z0.p(), target, beta);
        const PathVertex z[] = {z0, z1};
        const Vec3 wo = ps::direction(z1, z0);
        ps::Rng rng(ps::testseed::seed(7201), uint64_t(checked));
        for (int i = 0; i < 256; ++i) {
            const float uLight = rng.uniform();
            const Vec2 uPos = rng.uniform2();
            const ps::Connection c = ps::connectLight(scene(), z, 2, uLight, uPos);
            const ps::DirectSample d = ps::sampleDirectLight(scene(), z1.sp, wo, uLight, uPos);
            const Color expected = beta * d.value;
            float P = 0.0f;
            const int l = scene().selectLight(uLight, P);
            const char* kind = l == area ? "area light" : l == point ? "point light" : "background";
            const Color got = c.valid ? c.value : Color(0.0f);
            if (!close(got, expected) && wrongValue++ < 3)
                FAIL_CHECK(
                    "z_1 at "
                    << str(z1.p()) << ", the " << kind << " chosen (P(l) = " << num(P, 4)
                    << "): expected C* = beta_1 times lesson 2's "
                    << "light-sampling estimate = " << str(expected) << ", got valid = " << c.valid << ", "
                    << str(c.value) << " " << ratio(got, expected)
                    << ". Hints: C* = beta_z f Le G / p(y_0), p(y_0) = pdfLightOrigin includes P(l) (a ratio of 1 / P(l) "
                       "says it does not); G has both cosines and 1 / d^2 (lesson 6's geometryTerm); the shadow ray");
            if (ps::isBlack(d.value)) ++blocked;
            if (!c.valid) continue;
            ++seen[l == area ? 0 : l == point ? 1 : 2];
            const PathVertex& y0 = c.sampledLight;
            const bool flags =
                y0.onLight && y0.sp.light == l && y0.pointLight == (l == point) && y0.infinite == (l == bg);
            CHECK_MESSAGE(flags, "the " << kind << ": c.sampledLight must be its light vertex (onLight, sp.light = "
                                        << l << ", pointLight, infinite as for a light subpath's y_0); got onLight "
                                        << y0.onLight << ", sp.light " << y0.sp.light << ", pointLight "
                                        << y0.pointLight << ", infinite " << y0.infinite);
            const double pdf = l == area    ? double(P) / double(scene().lights[size_t(area)].area)
                               : l == point ? double(P)
                                            : double(P) / (4.0 * 3.14159265358979323846);
            CHECK_MESSAGE(std::abs(double(y0.pdfFwd) - pdf) <= 1e-4 * pdf,
                          "the " << kind << ": expected c.sampledLight.pdfFwd = P(l) "
                                 << (l == area    ? "/ area"
                                     : l == point ? ""
                                                  : "* the background's direction pdf")
                                 << " = " << num(pdf, 6) << " (Eq. 7.3), got " << num(y0.pdfFwd, 6));
            CHECK_MESSAGE(std::abs(double(y0.beta[0]) * pdf - 1.0) <= 1e-4,
                          "the " << kind << ": expected c.sampledLight.beta = 1 / pdfFwd, got " << str(y0.beta));
            if (l == bg)
                CHECK_MESSAGE(glm::dot(y0.sp.n, d.wi) > 0.999f,
                              "the background: c.sampledLight.sp.n must point from the scene towards "
                              "the background (the direction sampled), got "
                                  << str(y0.sp.n) << " for " << str(d.wi));
            else if (l == area)
                CHECK_MESSAGE(glm::length(y0.p() - (z1.p() + d.wi * glm::length(y0.p() - z1.p()))) < 1e-3f,
                              "the area light: c.sampledLight.sp.p must be the point sampleLight chose (in direction "
                                  << str(d.wi) << ")");
        }
        ++checked;
    }
    CHECK_MESSAGE(wrongValue == 0, wrongValue << " of the light samples' values differ (the first 3 above)");
    // Each kind must have been checked. With 64 samples per point the area light was valid 13.6 times
    // on average (sd 3.7, PATHSPACE_TEST_SEED 0-79) and "at least 10" failed at seed 7; with 256, about
    // 54 (area), 358 (point) and 67 (background): 20 is more than 4.5 sd below each.
    CHECK_MESSAGE(
        (seen[0] >= 20 && seen[1] >= 20 && seen[2] >= 20),
        "expected at least 20 valid connections to each of the area light, the point light and the background, got "
            << seen[0] << ", " << seen[1] << ", " << seen[2]);
    CHECK_MESSAGE(
        blocked >= 10,
        "test setup: expected some blocked light samples (the wall point behind the blocker), got " << blocked);
    {
        PathVertex zb = ps::backgroundVertex(scene(), Vec3(0.0f, 1.0f, 0.0f));
        zb.beta = beta;
        const PathVertex z1 = hit(z0.p(), Vec3(0.3f, 0.0f, 0.5f), beta);
        const PathVertex z[] = {z0, z1, zb};
        const ps::Connection c = ps::connectLight(scene(), z, 3, 0.1f, Vec2(0.5f, 0.5f));
        CHECK_MESSAGE(
            !c.valid,
            "z_2 at infinity: there is no point to sample a light for; expected no contribution, got " << str(c.value));
    }
}

TEST_CASE(
    "connectVertices (s, t >= 2): beta f G f beta with both cosines and 1/d^2, after the shadow ray, nothing at a mirror [2 pts]") {
    const PathVertex z0 = camera();
    const Color betaLight(2.0f, 2.0f, 2.0f), betaY(0.7f, 1.1f, 1.9f), betaZ(1.3f, 0.6f, 0.8f);
    const PathVertex y0 = hit(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.1f, 2.0f, 0.0f), betaLight);
    int cases = 0;
    // y_1 on the green wall, z_1 on the floor, at several distances and angles.
    for (const auto& [wallPoint, floorPoint] :
         {std::pair<Vec3, Vec3>{Vec3(-2.0f, 1.5f, 0.0f), Vec3(0.3f, 0.0f, 0.5f)},
          std::pair<Vec3, Vec3>{Vec3(-2.0f, 0.4f, -1.0f), Vec3(-1.2f, 0.0f, -0.8f)},
          std::pair<Vec3, Vec3>{Vec3(-2.0f, 2.5f, 0.5f), Vec3(1.0f, 0.0f, -1.5f)}}) {
        const PathVertex y1 = hit(y0.p(), wallPoint, betaY);
        const PathVertex z1 = hit(z0.p(), floorPoint, betaZ);
        REQUIRE(y1.sp.material == 1);
        REQUIRE(z1.sp.material == 0);
        const PathVertex y[] = {y0, y1}, z[] = {z0, z1};
        const ps::Connection c = ps::connectVertices(scene(), y, 2, z, 2);
        const Vec3 d = z1.p() - y1.p();
        const double d2 = double(glm::dot(d, d));
        const float G = float(cosAt(y1, z1.p()) * cosAt(z1, y1.p()) / d2);
        const Color expected = betaY * (kWall / kPi) * G * (kFloor / kPi) * betaZ;
        CHECK_MESSAGE((c.valid && close(c.value, expected)),
                      "y_1 on the wall at "
                          << str(y1.p()) << ", z_1 on the floor at " << str(z1.p()) << " (d^2 = " << num(d2, 5)
                          << "): expected C* = beta_y (0.2 0.6 0.4)/pi G (0.5 0.4 0.3)/pi beta_z = " << str(expected)
                          << ", got valid = " << c.valid << ", " << str(c.value) << " " << ratio(c.value, expected)
                          << ". A ratio of d^2 = " << num(d2, 5)
                          << ": 1 / d^2 missing; of 1 / cos = " << num(1.0 / cosAt(y1, z1.p()), 5) << " or "
                          << num(1.0 / cosAt(z1, y1.p()), 5) << ": a cosine missing (Eq. 7.4); else a beta or an f");
        ++cases;
    }
    // Blocked: the wall point behind the blocker, seen from the floor in front of it.
    {
        const PathVertex y1 = hit(y0.p(), Vec3(-2.0f, 0.6f, 2.0f), betaY);
        const PathVertex z1 = hit(z0.p(), Vec3(0.0f, 0.0f, 2.0f), betaZ);
        const PathVertex y[] = {y0, y1}, z[] = {z0, z1};
        REQUIRE(!ps::visible(scene(), y1, z1));
        const ps::Connection c = ps::connectVertices(scene(), y, 2, z, 2);
        CHECK_MESSAGE(!c.valid, "y_1 at "
                                    << str(y1.p()) << " and z_1 at " << str(z1.p())
                                    << " are separated by the blocker: expected no contribution (the shadow ray), got "
                                    << str(c.value));
    }
    // A mirror endpoint: a delta BSDF gives nothing for a given pair of directions.
    {
        const PathVertex y1 = hit(y0.p(), Vec3(1.5f, 0.5f, 1.5f), betaY);
        REQUIRE(y1.specular);
        const PathVertex z1 = hit(z0.p(), Vec3(0.3f, 0.0f, 0.5f), betaZ);
        const PathVertex y[] = {y0, y1}, z[] = {z0, z1};
        const ps::Connection c = ps::connectVertices(scene(), y, 2, z, 2);
        CHECK_MESSAGE((!c.valid && ps::isBlack(c.value)),
                      "y_1 on the mirror sphere: expected no contribution (f of a mirror is a delta, "
                      "0 for given directions), got "
                          << str(c.value));
    }
    // A background camera endpoint cannot be joined.
    {
        const PathVertex y1 = hit(y0.p(), Vec3(0.3f, 0.0f, 0.5f), betaY);
        const PathVertex z1 = hit(z0.p(), Vec3(-0.8f, 0.0f, 1.6f), betaZ);
        PathVertex zb = ps::backgroundVertex(scene(), Vec3(0.0f, 1.0f, 0.0f));
        zb.beta = betaZ;
        const PathVertex y[] = {y0, y1}, z[] = {z0, z1, zb};
        const ps::Connection c = ps::connectVertices(scene(), y, 2, z, 3);
        CHECK_MESSAGE(!c.valid,
                      "z_2 at infinity: it cannot be joined to y_1; expected no contribution, got " << str(c.value));
    }
    CHECK(cases == 3);
}
