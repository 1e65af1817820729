// Shared by lesson 6's graded tests: a small room of planes (a diffuse floor, a glossy back
// wall, an optional mirror, an area light and a point light), vertices built by hand on its
// planes, and the significance level of the statistical tests.
#pragma once
#include "alpha.h"
#include <doctest/doctest.h>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include "06-path-space/paths.h"
#include "format.h"
#include "lesson_files.h"
#include "image.h"
#include "render.h"
#include "scene_loader.h"
#include "render_helpers.h"
#include "statistics.h"

namespace lesson06 {

using ps::testfiles::loadSceneAt;
using ps::testfiles::readText;
using ps::testfiles::sourcePath;

using ps::Color;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;
using DVec3 = glm::dvec3;

// Statistical tests in this suite (every other check is exact or a finite-difference Jacobian):
//   z-tests of one technique's image against technique (1, k) on the Cornell box:
//            k = 2: (0,3), (2,1); k = 3: (0,4), (2,2), (3,1)                                -> 5
//   z-test of the sum over k = 1, 2, 3 of technique (1, k) against lesson 3's path tracer
//            at maxdepth 2                                                                  -> 1
// m = 6 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %: a correct implementation fails the whole graded suite by
// bad luck in fewer than 1 run in 100).
constexpr int kStatisticalTests = 6;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

constexpr double kPi = 3.14159265358979323846;

inline bool close(double a, double b, double rel) {
    return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b)) + 1e-30;
}

// The room: camera at (0, 1, -3) looking along +z (fov 60, 16 x 16); floor y = 0 (diffuse
// 0.5), back wall z = 2 (Phong exponent 4, albedo 0.6), an area light at y = 2 facing down
// (x, z in [-0.5, 0.5], emission 4 3 2), a point light at (1, 1.5, 0.5) (intensity 2), and a
// mirror x = -2 (albedo 0.9) on the left.
inline const char* roomText() {
    return "camera eye 0 1 -3  target 0 1 0  up 0 1 0  fov 60  resolution 16 16\n"
           "material floor diffuse albedo 0.5 0.5 0.5\n"
           "material wall phong albedo 0.6 0.6 0.6 exponent 4\n"
           "material mirror mirror albedo 0.9 0.9 0.9\n"
           "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material floor\n"
           "quad -2 0 2  -2 3 2  2 3 2  2 0 2  material wall\n"
           "quad -2 0 -2  -2 3 -2  -2 3 2  -2 0 2  material mirror\n"
           "quad -0.5 2 -0.5  0.5 2 -0.5  0.5 2 0.5  -0.5 2 0.5  emission 4 3 2\n"
           "pointlight position 1 1.5 0.5  intensity 2 2 2\n";
}
inline const ps::Scene& room() {
    static const ps::Scene s = ps::parseScene(roomText(), "the room (tests/06-path-space/lesson06.h)");
    return s;
}

inline int materialIndex(const ps::Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == name) return int(i);
    FAIL("test setup: no material " << name);
    return -1;
}
inline int lightOfKind(const ps::Scene& scene, ps::LightKind kind) {
    for (size_t i = 0; i < scene.lights.size(); ++i)
        if (scene.lights[i].kind == kind) return int(i);
    FAIL("test setup: no light of that kind");
    return -1;
}

// A vertex on a surface of material `material` at p with normal n, built by hand.
inline ps::PathVertex surface(const ps::Scene& scene, const Vec3& p, const Vec3& n, const std::string& material) {
    ps::PathVertex v;
    v.sp.p = p;
    v.sp.n = glm::normalize(n);
    v.sp.errScale = ps::maxAbsComponent(p);
    v.sp.material = materialIndex(scene, material);
    v.specular = scene.materials[size_t(v.sp.material)].isDelta();
    return v;
}
// A point on the area light (its normal as the scene built it: facing down).
inline ps::PathVertex areaLightPoint(const ps::Scene& scene, const Vec3& p) {
    const int l = lightOfKind(scene, ps::LightKind::Area);
    const ps::Light& light = scene.lights[size_t(l)];
    ps::PathVertex v;
    v.sp.p = p;
    v.sp.n = scene.triangles[scene.prims[light.prims[0]].index].normal();
    v.sp.errScale = ps::maxAbsComponent(p);
    v.sp.light = l;
    v.onLight = true;
    return v;
}
inline ps::PathVertex pointLightVertex(const ps::Scene& scene) {
    const int l = lightOfKind(scene, ps::LightKind::Point);
    ps::PathVertex v;
    v.sp.p = scene.lights[size_t(l)].position;
    v.sp.n = Vec3(0.0f, 1.0f, 0.0f);  // meaningless at a point light: must not be used
    v.sp.light = l;
    v.onLight = true;
    v.pointLight = true;
    return v;
}
inline ps::PathVertex pinhole(const ps::Scene& scene) { return ps::cameraVertex(scene); }

inline std::string describe(const ps::Path& x) {
    std::ostringstream s;
    for (size_t i = 0; i < x.size(); ++i) {
        const ps::PathVertex& v = x[i];
        s << (i ? " -> " : "") << "x" << i
          << (v.pointLight ? " (point light) "
              : v.onLight  ? " (light) "
              : v.pinhole  ? " (pinhole) "
              : v.specular ? " (specular) "
                           : " ")
          << str(v.sp.p);
    }
    return s.str();
}

using ps::testrender::Render;
using ps::testrender::sum;
using ps::testrender::total;

}  // namespace lesson06
