// Shared by lesson 5's graded tests: scenes at test resolution, renders through the registered
// integrators, the stored references, pixel masks, the significance level.
#pragma once
#include <doctest/doctest.h>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include "05-light-tracing/lighttracer.h"
#include "format.h"
#include "lesson_files.h"
#include "image.h"
#include "render.h"
#include "scene_loader.h"
#include "render_helpers.h"
#include "statistics.h"
#include "alpha.h"

namespace lesson05 {

using ps::testfiles::loadSceneAt;
using ps::testfiles::readText;
using ps::testfiles::sourcePath;

using ps::Color;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;

// Statistical tests in this suite (every other check is exact):
//   z-tests against stored path-traced references: the Cornell box, all pixels; its border
//            ring; each of its four edges (sum of the edge's pixels); the Cornell spheres away
//            from the spheres; the glass lamp                                              -> 8
//   t-tests: a point light in a sphere at 3 radii, and at maxdepth 1 and 2; a floor under
//            the sky (test_background.cpp)                                                 -> 6
// m = 14 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %: a correct implementation fails the whole graded suite by
// bad luck in fewer than 1 run in 100).
constexpr int kStatisticalTests = 14;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

using ps::testrender::Render;
// Lesson 5's renders run on two threads unless a test says otherwise.
inline Render render(const ps::Scene& scene, const std::string& algo, int iterations, uint64_t seed, int threads = 2) {
    return ps::testrender::render(scene, algo, iterations, seed, threads);
}

using ps::testrender::sum;
using ps::testrender::total;

// The pixels of img where mask is true, as a one-row image (for a z-test on part of an image).
inline ps::Image select(const ps::Image& img, const std::vector<bool>& mask) {
    int n = 0;
    for (bool m : mask) n += m;
    ps::Image out(n, 1);
    int k = 0;
    for (size_t i = 0; i < img.pixels.size(); ++i)
        if (mask[i]) out.pixels[size_t(k++)] = img.pixels[i];
    return out;
}

}  // namespace lesson05
