// Lesson 6, graded: the measurement contribution f(x) in three-point form (Eq. 6.3) of fixed
// paths in the room (lesson06.h), against values computed here from scratch in double: an area
// light and a point light over a diffuse floor, a glossy (Phong) bounce, a mirror (the
// coefficient of its delta, Eq. 6.11), and paths that must give 0 (occluded, a mirror with the
// wrong directions, light leaving the back of the light).
#include "lesson06.h"

using namespace lesson06;

namespace {

DVec3 d3(const Vec3& v) { return DVec3(v); }

// The pieces of Eq. 6.3, in double, independent of the code under test.
double G(const DVec3& a, const DVec3& na, bool pointA, const DVec3& b, const DVec3& nb, bool pointB) {
    const DVec3 d = b - a;
    const double d2 = glm::dot(d, d);
    const DVec3 w = d / std::sqrt(d2);
    return (pointA ? 1.0 : std::abs(glm::dot(na, w))) * (pointB ? 1.0 : std::abs(glm::dot(nb, w))) / d2;
}
// The pixel's sensor width * height * W_e at the pinhole (lesson 4): W_e = 1 / (A cos^4).
double sensor(const ps::Scene& scene, const DVec3& p) {
    const DVec3 e = d3(scene.camera.position()), f = d3(scene.camera.forward());
    const double cosT = glm::dot(glm::normalize(p - e), f);
    const double ty = std::tan(30.0 * kPi / 180.0), A = 4.0 * ty * ty;  // fov 60, square image
    return 16.0 * 16.0 / (A * std::pow(cosT, 4));
}
double phong(double albedo, double n, const DVec3& normal, const DVec3& wo, const DVec3& wi) {
    const DVec3 ns = glm::dot(normal, wo) < 0 ? -normal : normal;
    const DVec3 r = 2.0 * glm::dot(wo, ns) * ns - wo;
    const double c = glm::dot(r, wi);
    return c <= 0 ? 0.0 : albedo * (n + 2) / (2 * kPi) * std::pow(c, n);
}

bool black(const ps::DColor& c) { return c.x == 0.0 && c.y == 0.0 && c.z == 0.0; }

void checkColor(const ps::Path& x, const ps::DColor& got, const DVec3& expected, const std::string& what) {
    CHECK_MESSAGE((close(got.r, expected.x, 2e-4) && close(got.g, expected.y, 2e-4) && close(got.b, expected.z, 2e-4)),
                  what << ": path " << describe(x) << ": expected f = " << str(expected) << ", got " << str(got));
}

}  // namespace

TEST_CASE(
    "path space: f(x) of light -> diffuse floor -> pinhole, for an area light and a point light (Eq. 6.3) [2 pts]") {
    const ps::Scene& scene = room();
    const ps::PathVertex x0 = areaLightPoint(scene, Vec3(0.1f, 2.0f, -0.2f)), pl = pointLightVertex(scene);
    const ps::PathVertex x1 = surface(scene, Vec3(0.3f, 0.0f, 0.4f), Vec3(0, 1, 0), "floor"), cam = pinhole(scene);
    const DVec3 up(0, 1, 0), down(0, -1, 0), fwd = d3(scene.camera.forward());
    const DVec3 p0 = d3(x0.sp.p), p1 = d3(x1.sp.p), pc = d3(cam.sp.p), pp = d3(pl.sp.p);
    const double rest = 0.5 / kPi * G(p1, up, false, pc, fwd, false) * sensor(scene, p1);
    {
        const ps::Path x = {x0, x1, cam};
        const double g = G(p0, down, false, p1, up, false) * rest;
        checkColor(x, ps::contribution(scene, x), DVec3(4, 3, 2) * g, "area light (Le = (4, 3, 2))");
    }
    {
        const ps::Path x = {pl, x1, cam};
        const double g = G(pp, up, true, p1, up, false) * rest;
        checkColor(x, ps::contribution(scene, x), DVec3(2, 2, 2) * g,
                   "point light (intensity 2, no cosine at the light)");
    }
    {
        // Length 1: the light seen directly by the pinhole.
        const ps::Path x = {x0, cam};
        const double g = G(p0, down, false, pc, fwd, false) * sensor(scene, p0);
        checkColor(x, ps::contribution(scene, x), DVec3(4, 3, 2) * g, "length 1, the light seen directly");
    }
}

TEST_CASE(
    "path space: f(x) of longer paths: a glossy bounce and a mirror's delta coefficient (Eq. 6.3, 6.11) [2 pts]") {
    const ps::Scene& scene = room();
    const ps::PathVertex x0 = areaLightPoint(scene, Vec3(0.0f, 2.0f, 0.0f));
    const ps::PathVertex wall = surface(scene, Vec3(-0.4f, 0.8f, 2.0f), Vec3(0, 0, -1), "wall");
    const ps::PathVertex floor = surface(scene, Vec3(0.3f, 0.0f, 0.4f), Vec3(0, 1, 0), "floor"), cam = pinhole(scene);
    const DVec3 up(0, 1, 0), down(0, -1, 0), back(0, 0, -1), fwd = d3(scene.camera.forward());
    const DVec3 p0 = d3(x0.sp.p), pw = d3(wall.sp.p), pf = d3(floor.sp.p), pc = d3(cam.sp.p);
    {
        // light -> wall (Phong) -> floor -> pinhole. (Phong's f is symmetric in its arguments: the
        // argument order is graded by the refraction paths below, whose delta coefficient is not.)
        const ps::Path x = {x0, wall, floor, cam};
        const double fs = phong(0.6, 4, back, glm::normalize(pf - pw), glm::normalize(p0 - pw));
        const double g = G(p0, down, false, pw, back, false) * fs * G(pw, back, false, pf, up, false) * 0.5 / kPi *
                         G(pf, up, false, pc, fwd, false) * sensor(scene, pf);
        checkColor(x, ps::contribution(scene, x), DVec3(4, 3, 2) * g, "glossy wall (Phong exponent 4, albedo 0.6)");
    }
    {
        // light -> floor -> wall (Phong) -> pinhole.
        const ps::Path x = {x0, floor, wall, cam};
        const double fs = phong(0.6, 4, back, glm::normalize(pc - pw), glm::normalize(pf - pw));
        const double g = G(p0, down, false, pf, up, false) * 0.5 / kPi * G(pf, up, false, pw, back, false) * fs *
                         G(pw, back, false, pc, fwd, false) * sensor(scene, pw);
        checkColor(x, ps::contribution(scene, x), DVec3(4, 3, 2) * g, "glossy wall seen by the camera");
    }
    {
        // light -> mirror (x = -2) -> floor -> pinhole, the mirror point where the reflection
        // law holds: the reflection of the floor point in the mirror plane is (-4.3, 0, 0.4).
        const DVec3 img(-4.3, 0.0, 0.4);
        const double s = 2.0 / 4.3;
        const DVec3 pm = p0 + s * (img - p0);
        const ps::PathVertex mirror = surface(scene, Vec3(pm), Vec3(1, 0, 0), "mirror");
        const ps::Path x = {x0, mirror, floor, cam};
        const DVec3 nx(1, 0, 0);
        const double cosOut = std::abs(glm::dot(nx, glm::normalize(pf - pm)));
        const double g = G(p0, down, false, pm, nx, false) * (0.9 / cosOut) * G(pm, nx, false, pf, up, false) * 0.5 /
                         kPi * G(pf, up, false, pc, fwd, false) * sensor(scene, pf);
        checkColor(x, ps::contribution(scene, x), DVec3(4, 3, 2) * g,
                   "mirror (albedo 0.9): f_s is the delta's coefficient albedo / |cos theta_out|");
        // The same mirror vertex with a floor point off the reflection direction: 0.
        const ps::PathVertex off = surface(scene, Vec3(0.6f, 0.0f, 0.4f), Vec3(0, 1, 0), "floor");
        const ps::Path y = {x0, mirror, off, cam};
        const ps::DColor got = ps::contribution(scene, y);
        CHECK_MESSAGE(black(got), "path "
                                      << describe(y)
                                      << ": the directions at the mirror are not a reflected pair: expected f = 0, got "
                                      << str(got));
    }
}

TEST_CASE(
    "path space: f(x) is 0 for occluded edges and for light leaving the back of a one-sided light (Eq. 6.3) [1 pt]") {
    // The room with a square blocker at y = 1 between the light and the floor.
    const ps::Scene scene = ps::parseScene(
        std::string(roomText()) + "quad -0.2 1 -0.2  0.6 1 -0.2  0.6 1 0.8  -0.2 1 0.8  material floor\n",
        "the room with a blocker (test_contribution.cpp)");
    const ps::PathVertex x0 = areaLightPoint(scene, Vec3(0.1f, 2.0f, -0.2f)), cam = pinhole(scene);
    const ps::PathVertex x1 = surface(scene, Vec3(0.3f, 0.0f, 0.4f), Vec3(0, 1, 0), "floor");
    const ps::Path blocked = {x0, x1, cam};
    const ps::DColor got = ps::contribution(scene, blocked);
    CHECK_MESSAGE(black(got),
                  "path " << describe(blocked)
                          << ": the edge x0 x1 passes through a blocker at y = 1: expected f = 0 (V = 0), got "
                          << str(got));
    // Without the blocker, the same path is not 0 (so the 0 above is the visibility).
    const ps::DColor open =
        ps::contribution(room(), {areaLightPoint(room(), Vec3(0.1f, 2.0f, -0.2f)), x1, pinhole(room())});
    CHECK_MESSAGE(!black(open), "path " << describe(blocked) << " in the room without the blocker: expected f > 0, got "
                                        << str(open));
    // The light faces down: a wall point above its plane gets nothing from it.
    const ps::PathVertex high = surface(room(), Vec3(0.0f, 2.5f, 2.0f), Vec3(0, 0, -1), "wall");
    const ps::Path up = {areaLightPoint(room(), Vec3(0.0f, 2.0f, 0.0f)), high, pinhole(room())};
    const ps::DColor gotUp = ps::contribution(room(), up);
    CHECK_MESSAGE(black(gotUp),
                  "path " << describe(up)
                          << ": the area light emits only below (its normal faces -y): expected f = 0, got "
                          << str(gotUp));
    // A path that does not start on a light carries nothing (Le(x0) = 0), and one vertex is no path.
    const ps::Path dark = {x1, surface(room(), Vec3(-0.4f, 0.8f, 2.0f), Vec3(0, 0, -1), "wall"), pinhole(room())};
    const ps::DColor gotDark = ps::contribution(room(), dark);
    CHECK_MESSAGE(black(gotDark),
                  "path " << describe(dark) << ": x0 is on no light: expected f = 0, got " << str(gotDark));
    const ps::DColor gotOne = ps::contribution(room(), {pinhole(room())});
    CHECK_MESSAGE(black(gotOne), "a path of the pinhole alone (no edge): expected f = 0, got " << str(gotOne));
}
