// Shared by lesson 11's graded tests of the thin lens, bidirectional path tracing's t = 0 and
// distributed ray tracing (branch lens): the significance level, the test cameras, and the
// camera's geometry recomputed in double from its parameters alone (never from the pieces under
// test), so that the numerical checks are independent of your code.
#pragma once
#include "lesson11.h"
#include <doctest/doctest.h>
#include <cmath>
#include <string>
#include <vector>
#include "11-classics/distributed.h"
#include "11-classics/thinlens.h"
#include "format.h"
#include "lesson_files.h"
#include "render_helpers.h"
#include "scene_loader.h"
#include "seed.h"
#include "statistics.h"

namespace lens11 {

using ps::Color;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;
using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;
using DVec3 = glm::dvec3;

// Statistical tests of this part of lesson 11 (every other check is exact or a deterministic
// quadrature: the lens's points, rays, raster positions, W_e and densities, the t = 0 connection
// by hand, the MIS weights against lesson 6's densities, the refusals):
//   z-tests against the stored pt reference of the lens box: pt, lt, bpt                -> 3
//   bpt's t = 0 technique alone against s = 0 alone, per path length (image and total)   -> 1
//   drt against pt where both carry the same paths; drt against direct light in a
//   closed diffuse box                                                                     -> 2
//   drt against the stored reference of pt filtered to L D? (G|S)* E (the Cornell box
//   through the lens, where pt carries more paths)                                         -> 1
//   pt through the lens against the pinhole on a plane in focus (test_reach.cpp)          -> 1
// 8 of lesson 11's m = 16 (lesson11.h), each at lesson11::alpha().
using lesson11::alpha;                  // the lesson's level: all 16 of its statistical tests
using lesson11::kStatisticalTestsLens;  // counted in lesson11.h

// A thin-lens camera as the tests build it, and its geometry in double from the same numbers.
struct LensCase {
    const char* name;
    Vec3 eye, target, up;
    float fov;
    int w, h;
    float radius, focus;

    ps::ThinLens camera() const { return ps::ThinLens(ps::Camera(eye, target, up, fov, w, h), radius, focus); }
    std::string describe() const {
        return std::string(name) + " (eye " + str(eye) + ", target " + str(target) + ", fov " + num(fov) + ", " +
               std::to_string(w) + " x " + std::to_string(h) + ", lens radius " + num(radius) + ", focus " +
               num(focus) + ")";
    }
    // The camera's frame and image plane (at distance 1), as framework/camera.cpp defines them.
    DVec3 f() const { return glm::normalize(DVec3(target) - DVec3(eye)); }
    DVec3 r() const { return glm::normalize(glm::cross(f(), DVec3(up))); }
    DVec3 u() const { return glm::cross(r(), f()); }
    double ty() const { return std::tan(0.5 * double(fov) * 3.14159265358979323846 / 180.0); }
    double tx() const { return ty() * double(w) / double(h); }
    // The point of the plane of focus that raster (x, y) images (Eq. 11.12).
    DVec3 focal(double x, double y) const {
        const double sx = (2.0 * x / w - 1.0) * tx(), sy = (1.0 - 2.0 * y / h) * ty();
        return DVec3(eye) + double(focus) * (f() + sx * r() + sy * u());
    }
    // The raster position of a point q of the plane of focus (its inverse).
    Vec2 rasterOfFocal(const DVec3& q) const {
        const DVec3 d = (q - DVec3(eye)) / double(focus);
        const double sx = glm::dot(d, r()), sy = glm::dot(d, u());
        return Vec2(float((sx / tx() + 1.0) * 0.5 * w), float((1.0 - sy / ty()) * 0.5 * h));
    }
    // The point of the lens at polar coordinates (rho in [0, 1], phi), in double.
    DVec3 lensAt(double rho, double phi) const {
        return DVec3(eye) + double(radius) * rho * (std::cos(phi) * r() + std::sin(phi) * u());
    }
};

inline const std::vector<LensCase>& lensCases() {
    static const std::vector<LensCase> cases = {
        {"square image looking down +z", Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 16, 16, 0.3f, 2.0f},
        {"wide (fov 70), 24 x 12, oblique, large lens", Vec3(1, 2, 3), Vec3(4, -1, 5), Vec3(0, 0, 1), 70.0f, 24, 12,
         2.5f, 6.0f},
        {"tall 9 x 21, far from the origin, focused close", Vec3(-300, 120, 250), Vec3(-301, 119.5f, 240),
         Vec3(0.2f, 1, 0), 30.0f, 9, 21, 0.05f, 0.4f},
    };
    return cases;
}

// A fixed sequence of uniform numbers for Rng::replayFrom: values[0], values[1], ... then 0.5.
struct Replay : ps::UniformSource {
    std::vector<float> values;
    size_t read = 0;
    explicit Replay(std::vector<float> v) : values(std::move(v)) {}
    float next() override { return read < values.size() ? values[read++] : (++read, 0.5f); }
};

// The lens point lensPoint(u) in double.
inline DVec3 lensPointD(const ps::ThinLens& cam, const Vec2& u) { return DVec3(cam.lensPoint(u)); }

}  // namespace lens11
