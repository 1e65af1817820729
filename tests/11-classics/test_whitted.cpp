// Lesson 11, graded: Whitted's ray tracer (whitted.h, Eq. 11.7-11.9) on scenes and rays made by
// hand, against values computed here in double from the geometry: exact to float rounding, no
// statistics.
#include "paths_support.h"

using namespace lesson11paths;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A large diffuse floor (y = 0, albedo 0.6) under a point light at height h (intensity I), and
// whatever `extra` adds.
ps::Scene litFloor(const std::string& extra, const std::string& floorMaterial = "diffuse albedo 0.6 0.6 0.6") {
    return ps::parseScene(
        "camera eye 0 3 -6  target 0 0 0  fov 45  resolution 8 8\n"
        "material floor " +
            floorMaterial +
            "\n"
            "quad -50 0 -50  -50 0 50  50 0 50  50 0 -50  material floor\n"
            "pointlight position 0 2 0  intensity 5 4 3\n" +
            extra,
        "lit-floor.scene");
}

// The floor's surface point straight below (x, z), found by a ray as the integrators find it.
ps::SurfacePoint floorPoint(const ps::Scene& scene, float x, float z) {
    ps::Ray r(Vec3(x, 1.0f, z), Vec3(0, -1, 0));
    ps::SurfacePoint sp;
    REQUIRE(scene.intersect(r, sp));
    return sp;
}

// I cos / d^2 * albedo / pi at (x, 0, z) under the light (0, h, 0), in double.
Color lambertUnderLight(double x, double z, double h, const Color& I, double albedo) {
    const double d2 = x * x + z * z + h * h, cosTheta = h / std::sqrt(d2);
    const double f = albedo / kPi * cosTheta / d2;
    return Color(float(I.r * f), float(I.g * f), float(I.b * f));
}

bool close(const Color& a, const Color& b, double rel = 2e-5) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(double(a[c]) - double(b[c])) > rel * std::max(1e-12, std::abs(double(b[c])))) return false;
    return true;
}

}  // namespace

TEST_CASE("whittedDirect: a diffuse floor under a point light: I cos / d^2 albedo / pi, exactly [2 pts]") {
    const ps::Scene scene = litFloor("");
    const Color I(5, 4, 3);
    const float xs[][2] = {{0, 0}, {1, 0}, {0.5f, -1.5f}, {-3, 2}, {7, 5}};
    for (const auto& q : xs) {
        const ps::SurfacePoint sp = floorPoint(scene, q[0], q[1]);
        const Vec3 wo = glm::normalize(Vec3(0.3f, 1, -0.4f));
        const Color got = ps::whittedDirect(scene, sp, wo);
        const Color want = lambertUnderLight(q[0], q[1], 2.0, I, 0.6);
        const double d2 = double(q[0]) * q[0] + double(q[1]) * q[1] + 4.0;
        CHECK_MESSAGE(close(got, want), "floor point ("
                                            << q[0] << ", 0, " << q[1]
                                            << "), light 2 above the origin, I = (5, 4, 3), albedo "
                                            << "0.6: expected I cos(theta) / d^2 * albedo / pi = " << str(want)
                                            << ", got " << str(got) << " (d^2 = " << num(d2)
                                            << ", cos = " << num(2.0 / std::sqrt(d2)) << "; without 1/d^2 it would be x"
                                            << num(d2) << ", without the cosine x" << num(std::sqrt(d2) / 2.0) << ")");
    }
}

TEST_CASE("whittedDirect: a Phong floor reflects with its BSDF towards the viewer, and two point lights add [1 pt]") {
    const ps::Scene scene =
        litFloor("pointlight position 3 1 -1  intensity 2 2 2\n", "phong albedo 0.7 0.6 0.5  exponent 8");
    const ps::Material& m = scene.materials[0];
    const ps::SurfacePoint sp = floorPoint(scene, 1.0f, 0.5f);
    const Vec3 wo = glm::normalize(Vec3(-1.5f, 1.2f, -0.2f));
    Color want(0.0f);
    const struct {
        Vec3 p;
        Color I;
    } lights[] = {{Vec3(0, 2, 0), Color(5, 4, 3)}, {Vec3(3, 1, -1), Color(2, 2, 2)}};
    for (const auto& l : lights) {
        const Vec3 d = l.p - sp.p;
        const float d2 = glm::dot(d, d);
        const Vec3 w = d / std::sqrt(d2);
        want += ps::evalBSDF(m, sp.n, wo, w) * l.I * (std::abs(w.y) / d2);
    }
    const Color got = ps::whittedDirect(scene, sp, wo);
    CHECK_MESSAGE(close(got, want, 1e-4), "Phong floor (exponent 8) at (1, 0, 0.5) under two point lights: expected "
                                              << "the sum over both of f(wo, w_l) I_l cos / d^2 = " << str(want)
                                              << ", got " << str(got));
}

TEST_CASE("whittedDirect: a light hidden behind a wall gives nothing (a shadow ray per light) [1 pt]") {
    // A wall between the second light (x = 4) and the floor point at x = 1: only the first light counts.
    const ps::Scene scene = litFloor(
        "pointlight position 4 0.5 0  intensity 50 50 50\n"
        "material wall diffuse albedo 0.5 0.5 0.5\n"
        "quad 3 0 -2  3 0 2  3 3 2  3 3 -2  material wall\n");
    const ps::SurfacePoint sp = floorPoint(scene, 1.0f, 0.0f);
    const Color got = ps::whittedDirect(scene, sp, Vec3(0, 1, 0));
    const Color want = lambertUnderLight(1.0, 0.0, 2.0, Color(5, 4, 3), 0.6);
    CHECK_MESSAGE(close(got, want),
                  "floor point (1, 0, 0) with a wall at x = 3 between it and the light at (4, 0.5, 0): "
                  "expected only the unhidden light, "
                      << str(want) << ", got " << str(got) << " (the hidden one alone would add about "
                      << str(lambertUnderLight(3.0, 0.0, 0.5, Color(50), 0.6)) << ")");
    // Under the floor nothing is lit: the light is on the other side (f = 0 there).
    ps::SurfacePoint below = sp;
    CHECK_MESSAGE(ps::isBlack(ps::whittedDirect(scene, below, Vec3(0, -1, 0))),
                  "the floor seen from below: the lights are above it, expected black, got "
                      << str(ps::whittedDirect(scene, below, Vec3(0, -1, 0))));
}

TEST_CASE("glassSplit: Snell's directions, F and (1 - F)(eta_o / eta_t)^2, entering and leaving [2 pts]") {
    ps::Material glass;
    glass.kind = ps::BSDFKind::Dielectric;
    glass.ior = 1.5f;
    const Vec3 n(0, 1, 0);
    for (double deg : {0.0, 30.0, 45.0, 70.0}) {
        for (bool inside : {false, true}) {
            const double th = deg * kPi / 180.0;
            const Vec3 wo = Vec3(float(std::sin(th)), float(inside ? -std::cos(th) : std::cos(th)), 0.0f);
            const double etaO = inside ? 1.5 : 1.0, etaT = inside ? 1.0 : 1.5;
            const double sinT = etaO / etaT * std::sin(th);
            const ps::GlassSplit g = ps::glassSplit(glass, n, wo);
            CAPTURE(deg);
            CAPTURE(inside);
            const std::string where = std::string(inside ? "from inside the glass (eta_o = 1.5, eta_t = 1)"
                                                         : "from outside (eta_o = 1, eta_t = 1.5)") +
                                      " at " + num(deg) + " degrees";
            const Vec3 refl(-wo.x, wo.y, 0.0f);
            CHECK_MESSAGE(glm::length(g.reflected - refl) < 1e-5f,
                          where << ": reflected expected " << str(refl) << ", got " << str(g.reflected));
            if (sinT >= 1.0) {
                CHECK_MESSAGE((g.reflectance == 1.0f && g.transmission == 0.0f),
                              where << ": total internal reflection (sin theta_t = " << num(sinT)
                                    << " > 1): expected F = 1 and no refraction, got F = " << g.reflectance
                                    << ", transmission " << g.transmission);
                continue;
            }
            const double cosT = std::sqrt(1.0 - sinT * sinT);
            const Vec3 refr(float(-sinT), float(inside ? cosT : -cosT), 0.0f);
            const float F = ps::fresnelDielectric(float(std::cos(th)), float(etaO), float(etaT));
            const double T = (1.0 - F) * (etaO / etaT) * (etaO / etaT);
            CHECK_MESSAGE(glm::length(g.refracted - refr) < 1e-5f, where << ": refracted expected " << str(refr)
                                                                         << " (sin theta_t = " << num(sinT) << "), got "
                                                                         << str(g.refracted));
            CHECK_MESSAGE(std::abs(g.reflectance - F) < 1e-6f,
                          where << ": reflectance expected F = " << F << ", got " << g.reflectance);
            CHECK_MESSAGE(
                std::abs(g.transmission - T) < 1e-5 * T,
                where << ": transmission expected (1 - F)(eta_o / eta_t)^2 = " << num(T) << ", got " << g.transmission);
        }
    }
}

TEST_CASE("LiWhitted: a mirror in front of the lit floor, and the maximum depth (E S D L has 2 bounces) [2 pts]") {
    // A mirror (albedo 0.8) in the plane x = 2, facing -x. A ray from (0, 1, 0) towards the
    // mirror and down reflects onto the floor at P; what comes back is 0.8 times the floor's
    // radiance at P towards the mirror: 0.8 I cos / d^2 albedo / pi (whittedDirect's formula).
    ps::Scene scene = litFloor(
        "material m mirror albedo 0.8 0.8 0.8\n"
        "quad 2 0 -3  2 3 -3  2 3 3  2 0 3  material m\n");
    const Vec3 o(0, 1, 0);
    const Vec3 d = glm::normalize(Vec3(2.0f, -0.8f, 0.3f));
    // The mirror at t1 = 2 / d.x; the reflected direction (-d.x, d.y, d.z) reaches y = 0 at P.
    const double t1 = 2.0 / d.x, y1 = 1.0 + t1 * d.y, z1 = t1 * d.z;
    const double t2 = y1 / -d.y;
    const double px = 2.0 - t2 * d.x, pz = z1 + t2 * d.z;
    const Color floorValue = lambertUnderLight(px, pz, 2.0, Color(5, 4, 3), 0.6);
    const Color want = 0.8f * floorValue;
    for (int maxDepth : {0, 1, 2, 3}) {
        ps::WhittedOptions opt;
        opt.maxDepth = maxDepth;
        const Color got = ps::LiWhitted(scene, ps::Ray(o, d), 0, opt);
        const Color expected = maxDepth >= 2 ? want : Color(0.0f);
        CHECK_MESSAGE(close(got, expected, 1e-4),
                      "eye -> mirror -> floor -> light is E S D L, 2 bounces; with maxDepth "
                          << maxDepth << " expected " << str(expected)
                          << (maxDepth < 2 ? " (the path is too long)" : "") << ", got " << str(got)
                          << " (floor point (" << num(px) << ", 0, " << num(pz) << "))");
    }
    // The floor seen directly: one bounce (E D L).
    const Vec3 down = glm::normalize(Vec3(0.5f, -1, 0.2f));
    for (int maxDepth : {0, 1}) {
        ps::WhittedOptions opt;
        opt.maxDepth = maxDepth;
        const Color got = ps::LiWhitted(scene, ps::Ray(o, down), 0, opt);
        const Color expected =
            maxDepth >= 1 ? lambertUnderLight(0.5 / 1.0, 0.2, 2.0, Color(5, 4, 3), 0.6) : Color(0.0f);
        CHECK_MESSAGE(close(got, expected, 1e-4), "the floor seen directly (E D L, 1 bounce) with maxDepth "
                                                      << maxDepth << ": expected " << str(expected) << ", got "
                                                      << str(got));
    }
}

TEST_CASE(
    "LiWhitted: glass splits into F times the reflected and (1 - F)(eta_o / eta_t)^2 times the refracted "
    "radiance, entering and leaving [2 pts]") {
    // A glass interface y = 1 (air above, glass below), a background of radiance B, and two small
    // lamps: one at y = -3 facing up where the refracted ray of a 45 degree ray from above lands,
    // one at y = 2 facing down where a ray from inside at 30 degrees leaves. A ray not bent by
    // Snell's law, or bent by the inverse ratio, misses its lamp; the reflected rays miss both.
    const double sinIn = std::sin(kPi / 4) / 1.5, tanIn = sinIn / std::sqrt(1 - sinIn * sinIn);  // 45 deg in
    const double sinOut = 1.5 * 0.5, tanOut = sinOut / std::sqrt(1 - sinOut * sinOut);           // 30 deg out
    const auto lamp = [](double cx, double y, bool up, const char* Le) {
        const double a = cx - 0.08, b = cx + 0.08;
        const std::string A = num(a), Bx = num(b), Y = num(y);
        return up ? "quad " + A + " " + Y + " -0.08  " + A + " " + Y + " 0.08  " + Bx + " " + Y + " 0.08  " + Bx + " " +
                        Y + " -0.08  emission " + Le + "\n"
                  : "quad " + A + " " + Y + " -0.08  " + Bx + " " + Y + " -0.08  " + Bx + " " + Y + " 0.08  " + A +
                        " " + Y + " 0.08  emission " + Le + "\n";
    };
    const ps::Scene scene = ps::parseScene(
        "camera eye 0 3 -6  target 0 0 0  fov 45  resolution 8 8\n"
        "material glass dielectric ior 1.5\n"
        "quad -20 1 -20  -20 1 20  20 1 20  20 1 -20  material glass\n" +  // normal +y: air above
            lamp(4 * tanIn, -3.0, true, "3 2 1") +
            lamp(tanOut, 2.0, false, "1 2 4") + "background radiance 0.5 0.25 1\n",
        "glass-interface.scene");
    const Color B(0.5f, 0.25f, 1.0f);
    ps::WhittedOptions opt;
    opt.maxDepth = 3;
    {  // from above at 45 degrees, hitting the interface at the origin's x
        const Vec3 d = glm::normalize(Vec3(1, -1, 0));
        const Color got = ps::LiWhitted(scene, ps::Ray(Vec3(-1, 2, 0), d), 0, opt);
        const float F = ps::fresnelDielectric(std::cos(float(kPi / 4)), 1.0f, 1.5f);
        const Color want = F * B + (1 - F) / 2.25f * Color(3, 2, 1);
        CHECK_MESSAGE(close(got, want, 1e-4),
                      "a ray entering glass at 45 degrees: expected F B + (1 - F)(1/1.5)^2 Le = "
                          << str(want) << " (F = " << F << "), got " << str(got));
    }
    {  // from inside at 30 degrees, leaving the glass upwards
        const Vec3 d = glm::normalize(Vec3(0.5f, float(std::sqrt(3.0) / 2), 0));
        const Vec3 o = Vec3(0, 1, 0) - d * (0.5f / d.y);
        const Color got = ps::LiWhitted(scene, ps::Ray(o, d), 0, opt);
        const float F = ps::fresnelDielectric(float(std::sqrt(3.0) / 2), 1.5f, 1.0f);
        const Color want = F * B + (1 - F) * 2.25f * Color(1, 2, 4);
        CHECK_MESSAGE(close(got, want, 1e-4),
                      "a ray leaving glass at 30 degrees (inside: eta_o = 1.5): expected F B + "
                      "(1 - F)(1.5/1)^2 Le = "
                          << str(want) << " (F = " << F << "), got " << str(got));
    }
    {  // from inside at 50 degrees: total internal reflection, the ray goes back down to the background
        const Vec3 d = glm::normalize(Vec3(float(std::sin(50 * kPi / 180)), float(std::cos(50 * kPi / 180)), 0));
        const Vec3 o = Vec3(0, 1, 0) - d * (0.5f / d.y);
        const Color got = ps::LiWhitted(scene, ps::Ray(o, d), 0, opt);
        CHECK_MESSAGE(close(got, B, 1e-5),
                      "a ray inside glass meeting the interface at 50 degrees (beyond the critical "
                      "angle 41.8): total internal reflection, expected B = "
                          << str(B) << ", got " << str(got));
    }
}

TEST_CASE(
    "LiWhitted: the ambient term is ambient x albedo where nothing else lights a surface, and only if asked "
    "[1 pt]") {
    // A floor point in the shadow of a roof between it and the light, and a mirror facing the sky.
    const ps::Scene scene = litFloor(
        "material roof diffuse albedo 0.5 0.5 0.5\n"
        "quad -1 1 -1  1 1 -1  1 1 1  -1 1 1  material roof\n"
        "material m mirror\n"
        "quad 5 0.01 -1  5 0.01 1  7 0.01 1  7 0.01 -1  material m\n");
    const ps::Ray shadowed(Vec3(0.2f, 0.5f, -3), glm::normalize(Vec3(0, -0.5f, 3.1f)));
    const ps::Ray onMirror(Vec3(6, 2, 0), Vec3(0, -1, 0));
    ps::WhittedOptions opt;
    opt.maxDepth = 4;
    const Color none = ps::LiWhitted(scene, shadowed, 0, opt);
    CHECK_MESSAGE(ps::isBlack(none),
                  "a floor point in the roof's shadow, ambient 0: expected black, got " << str(none));
    opt.ambient = Color(0.1f, 0.2f, 0.3f);
    const Color amb = ps::LiWhitted(scene, shadowed, 0, opt);
    const Color want = Color(0.1f, 0.2f, 0.3f) * 0.6f;
    CHECK_MESSAGE(close(amb, want),
                  "a floor point in the roof's shadow (albedo 0.6), ambient (0.1, 0.2, 0.3): expected "
                  "ambient x albedo = "
                      << str(want) << ", got " << str(amb));
    const Color sky = ps::LiWhitted(scene, onMirror, 0, opt);
    CHECK_MESSAGE(ps::isBlack(sky),
                  "a mirror that sees only the black sky, ambient (0.1, 0.2, 0.3): expected black "
                  "(a mirror reflects, it is not shaded), got "
                      << str(sky));
}
