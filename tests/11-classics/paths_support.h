// Shared by lesson 11's graded tests of the `paths` part (Heckbert's classification, Whitted):
// the significance level, a scene with one material of every kind, vertices made by hand.
#pragma once
#include "lesson11.h"
#include <doctest/doctest.h>
#include <cmath>
#include <string>
#include <vector>
#include "11-classics/heckbert.h"
#include "11-classics/whitted.h"
#include "format.h"
#include "lesson_files.h"
#include "render_helpers.h"
#include "scene_loader.h"
#include "seed.h"
#include "statistics.h"

namespace lesson11paths {

using ps::Color;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;
using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;

// Statistical tests of this part (every other check is exact: the types of hand-made paths, the
// point lights' sums, the glass's directions and weights, rays traced by hand):
//   z-test: whitted on scenes/cornell-whitted.scene against the stored pt reference filtered to
//           L[DG]S*E|LS*E (test_whitted_pt.cpp)                                              -> 1
// 1 of lesson 11's m = 16 (lesson11.h), at lesson11::alpha().
using lesson11::alpha;                   // the lesson's level: all 16 of its statistical tests
using lesson11::kStatisticalTestsPaths;  // counted in lesson11.h

// One material of every kind, an area light whose surface is the loader's black "(emitter)", a
// white quad that emits too, a point light and the background.
inline ps::Scene everyKind() {
    return ps::parseScene(
        "camera eye 0 1 -4  target 0 0.5 0  fov 45  resolution 8 8\n"
        "material white  diffuse albedo 0.8 0.8 0.8\n"
        "material gloss  phong albedo 0.5 0.5 0.5  exponent 20\n"
        "material flat   phong albedo 0.5 0.5 0.5  exponent 0\n"
        "material chrome mirror albedo 0.9 0.9 0.9\n"
        "material glass  dielectric ior 1.5\n"
        "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material white\n"                  // floor
        "quad -0.5 2 -0.5  0.5 2 -0.5  0.5 2 0.5  -0.5 2 0.5  emission 5 5 5\n"  // lamp
        "quad -2 0 2  2 0 2  2 2 2  -2 2 2  material white  emission 1 1 1\n"    // glowing wall
        "pointlight position 0 1.5 0  intensity 3 3 3\n"
        "background radiance 0.2 0.2 0.2\n",
        "every-kind.scene");
}

inline int materialIndex(const ps::Scene& scene, const std::string& name) {
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == name) return int(i);
    FAIL("no material '" << name << "' in the test scene");
    return -1;
}
inline int lightIndex(const ps::Scene& scene, ps::LightKind kind, bool withMaterial = false) {
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        const ps::Light& l = scene.lights[i];
        if (l.kind != kind) continue;
        if (kind != ps::LightKind::Area) return int(i);
        const int m = scene.prims[l.prims[0]].material;
        if ((scene.materials[size_t(m)].name == "white") == withMaterial) return int(i);
    }
    FAIL("no such light in the test scene");
    return -1;
}

// A vertex on a surface of the named material, at p; onLight: it lies on light `light`.
inline ps::PathVertex surface(const ps::Scene& scene, const std::string& material, const Vec3& p, int light = -1) {
    ps::PathVertex v;
    v.sp.p = p;
    v.sp.n = Vec3(0, 1, 0);
    v.sp.material = materialIndex(scene, material);
    v.sp.light = light;
    v.onLight = light >= 0;
    v.specular = scene.materials[size_t(v.sp.material)].isDelta();
    return v;
}
// x_0 on the area light (the black "(emitter)" surface of the lamp, or the glowing white wall).
inline ps::PathVertex onAreaLight(const ps::Scene& scene, bool glowingWall) {
    const int l = lightIndex(scene, ps::LightKind::Area, glowingWall);
    ps::PathVertex v;
    v.sp.p = glowingWall ? Vec3(0, 1, 2) : Vec3(0, 2, 0);
    v.sp.n = glowingWall ? Vec3(0, 0, -1) : Vec3(0, -1, 0);
    v.sp.material = scene.prims[scene.lights[size_t(l)].prims[0]].material;
    v.sp.light = l;
    v.onLight = true;
    return v;
}
inline ps::PathVertex onPointLight(const ps::Scene& scene) {
    ps::PathVertex v;
    v.sp.p = Vec3(0, 1.5f, 0);
    v.sp.light = lightIndex(scene, ps::LightKind::Point);
    v.onLight = v.pointLight = true;
    return v;
}

}  // namespace lesson11paths
