// Shared by lesson 0's graded tests: exact (double precision) expected values for camera rays
// and ray/triangle hits, and printing helpers so that every failure names the ray and the
// triangle. Every test is deterministic (fixed seeds), so a submission scores the same each run.
#pragma once
#include <cmath>
#include <sstream>
#include <string>
#include <vector>
#include "camera.h"
#include "format.h"
#include "geometry.h"
#include "rng.h"

namespace lesson00 {

using ps::fmt::str;  // Vec2, Vec3, dvec3 (tests/support/format.h)

using ps::Ray;
using ps::Triangle;
using ps::Vec2;
using ps::Vec3;
using DVec3 = glm::dvec3;

inline std::string str(const Ray& r) {
    std::ostringstream s;
    s.precision(9);
    s << "ray origin " << str(r.o) << " direction " << str(r.d) << " tMax " << r.tMax;
    return s.str();
}
inline std::string str(const Triangle& t) {
    return "triangle p0 " + str(t.p0) + " p1 " + str(t.p1) + " p2 " + str(t.p2);
}

// Counts the checks of one test and their failures; only the first kShown failures are printed
// in full (a wrong formula fails thousands of checks the same way), then one summary line.
struct Tally {
    static constexpr int kShown = 5;
    int checks = 0, failures = 0;
    // Records one check; true if its failure should be printed.
    bool fail(bool ok) {
        ++checks;
        return !ok && ++failures <= kShown;
    }
};
// The summary line: a test passes only if every one of its checks passed.
#define LESSON00_SUMMARY(tally, what)                                                                               \
    CHECK_MESSAGE((tally).failures == 0, "expected all " << (tally).checks << " " << (what) << " to be right, got " \
                                                         << (tally).failures << " wrong"                            \
                                                         << std::string((tally).failures > lesson00::Tally::kShown  \
                                                                            ? " (the first 5 are shown above)"      \
                                                                            : ""))

// ---------------------------------------------------------------------------------------------
// Camera: the parameters a test builds a camera from, and the exact ray it must generate.

struct CameraSpec {
    Vec3 eye, target, up;
    float fovY;
    int width, height;
    ps::Camera make() const { return ps::Camera(eye, target, up, fovY, width, height); }
    std::string describe() const {
        std::ostringstream s;
        s << "camera eye " << str(eye) << " target " << str(target) << " up " << str(up) << " fovY " << fovY
          << " image " << width << "x" << height;
        return s.str();
    }
};

// The camera basis of framework/camera.h, in double: forward f towards the target,
// right r = normalize(f x up), up' u = r x f (so the image's "up" is u, "right" is r).
struct ExactBasis {
    DVec3 f, r, u;
    double tanX, tanY;
};
inline ExactBasis exactBasis(const CameraSpec& c) {
    ExactBasis b;
    b.f = glm::normalize(DVec3(c.target) - DVec3(c.eye));
    b.r = glm::normalize(glm::cross(b.f, DVec3(c.up)));
    b.u = glm::cross(b.r, b.f);
    b.tanY = std::tan(0.5 * double(c.fovY) * 3.14159265358979323846 / 180.0);
    b.tanX = b.tanY * c.width / c.height;
    return b;
}

// Eq. 0.1 and 0.2 in double: the unit direction through raster position (x, y).
inline DVec3 exactDirection(const CameraSpec& c, double x, double y) {
    const ExactBasis b = exactBasis(c);
    const double sx = (2.0 * x / c.width - 1.0) * b.tanX;
    const double sy = (1.0 - 2.0 * y / c.height) * b.tanY;
    return glm::normalize(b.f + sx * b.r + sy * b.u);
}

// Largest component difference between a float direction and the exact one.
inline double maxDiff(const Vec3& a, const DVec3& b) {
    const DVec3 d = glm::abs(DVec3(a) - b);
    return std::max(d.x, std::max(d.y, d.z));
}

// Tolerance on each component of a unit direction: the camera's basis and tan(fovY / 2) are
// float (relative error ~1e-7); 2e-6 leaves room for any reasonable order of operations.
constexpr double kDirTol = 2e-6;

// ---------------------------------------------------------------------------------------------
// Ray/triangle helpers.

struct Hit {
    bool hit = false;
    float t = -1.0f, b1 = -1.0f, b2 = -1.0f;
};
inline Hit intersect(const Ray& ray, const Triangle& tri) {
    Hit h;
    const ps::WatertightRay wr(ray);
    h.hit = ps::intersectTriangle(ray, wr, tri, h.t, h.b1, h.b2);
    return h;
}
inline std::string str(const Hit& h) {
    std::ostringstream s;
    s.precision(9);
    if (!h.hit) return "no hit";
    s << "hit at t = " << h.t << " with b1 = " << h.b1 << ", b2 = " << h.b2;
    return s.str();
}

// The exact distance along the (float) ray to the (float) triangle's plane, in double.
inline double exactT(const Ray& ray, const Triangle& tri) {
    const DVec3 p0(tri.p0), n = glm::cross(DVec3(tri.p1) - p0, DVec3(tri.p2) - p0);
    return glm::dot(n, p0 - DVec3(ray.o)) / glm::dot(n, DVec3(ray.d));
}

// The exact hit of the (float) ray with the (float) triangle's plane, in double: t and the
// barycentric weights (b1, b2) of p1 and p2 of the point o + t d.
struct ExactHit {
    double t, b1, b2;
};
inline ExactHit exactHit(const Ray& ray, const Triangle& tri) {
    const DVec3 p0(tri.p0), e1 = DVec3(tri.p1) - p0, e2 = DVec3(tri.p2) - p0, n = glm::cross(e1, e2);
    ExactHit h;
    h.t = exactT(ray, tri);
    const DVec3 x = DVec3(ray.o) + h.t * DVec3(ray.d) - p0;
    h.b1 = glm::dot(glm::cross(x, e2), n) / glm::dot(n, n);
    h.b2 = glm::dot(glm::cross(e1, x), n) / glm::dot(n, n);
    return h;
}

// The point of a triangle at barycentrics (b1, b2), in float, the way Scene computes hit points.
inline Vec3 pointAt(const Triangle& t, float b1, float b2) { return (1.0f - b1 - b2) * t.p0 + b1 * t.p1 + b2 * t.p2; }

inline Vec3 randomUnit(ps::Rng& rng) {
    const float z = 1.0f - 2.0f * rng.uniform(), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * ps::kPi * rng.uniform();
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// A unit direction whose cosine with the unit vector n is c (c < 0: the other side of n).
inline Vec3 directionWithCos(const Vec3& n, float c, ps::Rng& rng) {
    const float s = std::sqrt(std::max(0.0f, 1.0f - c * c)), phi = 2.0f * ps::kPi * rng.uniform();
    const ps::Frame f(n);
    return glm::normalize(f.toWorld(Vec3(s * std::cos(phi), s * std::sin(phi), c)));
}

}  // namespace lesson00
