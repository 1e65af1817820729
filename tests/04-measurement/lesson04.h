// Shared by lesson 4's graded tests: cameras, exact solid angles of image-plane rectangles and
// integrals over them, the scenes, a direction sampler independent of the camera's, the
// significance level.
#pragma once
#include <doctest/doctest.h>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include "04-measurement/measurement.h"
#include "format.h"
#include "lesson_files.h"
#include "image.h"
#include "scene_loader.h"
#include "render_helpers.h"
#include "statistics.h"
#include "alpha.h"

namespace lesson04 {

using ps::testfiles::loadSceneAt;
using ps::testfiles::readText;
using ps::testfiles::sourcePath;

using ps::Color;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;

// Statistical tests in this suite (every other check is exact or a deterministic quadrature):
//   z-tests: a pixel measured as <W_e, L> against the path-traced reference, 3 pixels  -> 3
//   t-tests: flux through a patch under a point light and under an area light         -> 2
// m = 5 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %: a correct implementation fails the whole graded suite by
// bad luck in fewer than 1 run in 100).
constexpr int kStatisticalTests = 5;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

// The cameras of the W_e tests; the second is the wide-angle one (a corner pixel at 74 degrees
// from the axis, where cos^4 = 0.006).
struct CameraCase {
    std::string name;
    Vec3 eye, target, up;
    float fov;
    int w, h;
    ps::Camera make() const { return ps::Camera(eye, target, up, fov, w, h); }
};
inline const CameraCase kCameras[] = {
    {"fov 40, 64 x 48, looking down +z", Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 64, 48},
    {"wide angle: fov 120, 160 x 90, oblique", Vec3(1, 2, 3), Vec3(4, -1, 5), Vec3(0, 0, 1), 120.0f, 160, 90},
    {"fov 25, 33 x 101 (tall, odd)", Vec3(-2, 0.5f, 7), Vec3(-2.5f, 0.25f, -3), Vec3(0.2f, 1, 0), 25.0f, 33, 101},
};

// The camera's image plane at distance 1, recovered from generateRay alone (lesson 0): forward,
// the unit vectors along +x (right) and -y (up) of the raster, and the half-extents tx, ty.
struct ImagePlane {
    glm::dvec3 f, r, u;
    double tx = 1, ty = 1;
    int w = 1, h = 1;
    // Unit direction through the image-plane point (sx, sy) (sx right, sy up).
    glm::dvec3 dir(double sx, double sy) const { return glm::normalize(f + sx * r + sy * u); }
    // Image-plane coordinates of raster position (x, y) (y grows downward).
    glm::dvec2 ofRaster(double x, double y) const { return {(2.0 * x / w - 1.0) * tx, (1.0 - 2.0 * y / h) * ty}; }
};
inline ImagePlane planeOf(const ps::Camera& cam) {
    ImagePlane p;
    p.w = cam.width();
    p.h = cam.height();
    p.f = glm::dvec3(cam.forward());
    const glm::dvec3 dr(cam.generateRay(Vec2(float(cam.width()), 0.5f * cam.height())).d);
    const glm::dvec3 du(cam.generateRay(Vec2(0.5f * cam.width(), 0.0f)).d);
    const glm::dvec3 rr = dr / glm::dot(dr, p.f) - p.f, uu = du / glm::dot(du, p.f) - p.f;  // on the plane z = 1
    p.tx = glm::length(rr);
    p.ty = glm::length(uu);
    p.r = rr / p.tx;
    p.u = uu / p.ty;
    return p;
}

// Solid angle of the spherical triangle (a, b, c), unit vectors (Van Oosterom & Strackee 1983):
// tan(Omega / 2) = |a . (b x c)| / (1 + a.b + b.c + c.a).
inline double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const double numer = std::abs(glm::dot(a, glm::cross(b, c)));
    const double denom = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
    return 2.0 * std::atan2(numer, denom);
}
// Solid angle seen through the image-plane rectangle [x0, x1] x [y0, y1].
inline double rectSolidAngle(const ImagePlane& p, double x0, double y0, double x1, double y1) {
    const glm::dvec3 a = p.dir(x0, y0), b = p.dir(x1, y0), c = p.dir(x1, y1), d = p.dir(x0, y1);
    return triangleSolidAngle(a, b, c) + triangleSolidAngle(a, c, d);
}

// Integral of g(direction) over the directions through the image-plane rectangle
// [x0, x1] x [y0, y1], on an n x n grid: sum of g(cell centre) * (exact solid angle of the cell).
inline double integrateOverRect(const ImagePlane& p, double x0, double y0, double x1, double y1, int n,
                                const std::function<double(const Vec3&)>& g) {
    double sum = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double xa = x0 + (x1 - x0) * i / n, xb = x0 + (x1 - x0) * (i + 1) / n;
            const double ya = y0 + (y1 - y0) * j / n, yb = y0 + (y1 - y0) * (j + 1) / n;
            sum += g(Vec3(p.dir(0.5 * (xa + xb), 0.5 * (ya + yb)))) * rectSolidAngle(p, xa, ya, xb, yb);
        }
    return sum;
}

// Directions uniform in a cone around a unit axis, 1 - cos(half-angle) = oneMinusCosMax: a way
// to pick directions that has nothing to do with the camera's (density 1 / (2 pi oneMinusCosMax)).
inline glm::dvec3 sampleCone(double u1, double u2, double oneMinusCosMax, const glm::dvec3& axis) {
    const double oneMinusCos = u1 * oneMinusCosMax, sinTheta = std::sqrt(oneMinusCos * (2.0 - oneMinusCos));
    const double phi = 2.0 * 3.14159265358979323846 * u2;
    const glm::dvec3 a = std::abs(axis.x) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const glm::dvec3 s = glm::normalize(glm::cross(axis, a)), t = glm::cross(axis, s);
    return glm::normalize(sinTheta * std::cos(phi) * s + sinTheta * std::sin(phi) * t + (1.0 - oneMinusCos) * axis);
}

using ps::testrender::sum;

}  // namespace lesson04
