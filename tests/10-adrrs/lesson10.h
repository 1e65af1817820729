// Shared by lesson 10's graded tests: the significance level, a replayed sequence of uniform
// numbers, small scenes written in the test.
#pragma once
#include "alpha.h"
#include <doctest/doctest.h>
#include <cmath>
#include <string>
#include <vector>
#include "10-adrrs/adrrs.h"
#include "format.h"
#include "lesson_files.h"
#include "render_helpers.h"
#include "scene_loader.h"
#include "seed.h"
#include "statistics.h"

namespace lesson10 {

using ps::Color;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;
using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;

// Statistical tests in this suite (every other check is exact: the number of continuations over
// a grid of u, the weights, the window, the cache, the walk's tree, the counts against their replay):
//   z-tests: pt-adrrs on the Cornell box against lesson 3's stored reference, with the
//            pre-pass's cache and with a random cache, per pixel and the whole image's mean -> 4
//   the wasted-vertex comparisons with lesson 3's roulette on the skylight and the door: bounds
//            at least 4.1 standard deviations of their spread over seeds from its mean, which
//            alpha() (3.7 sd one-sided) covers (test_wasted.cpp)                       -> 2
// m = 6 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %: a correct implementation fails the whole graded suite by
// bad luck in fewer than 1 run in 100).
constexpr int kStatisticalTests = 6;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

// A fixed sequence of uniform numbers for Rng::replayFrom: values[0], values[1], ... then
// `fill` forever; counts what was read.
struct Replay : ps::UniformSource {
    std::vector<float> values;
    float fill = 0.5f;
    size_t read = 0;
    float next() override {
        const float u = read < values.size() ? values[read] : fill;
        ++read;
        return u;
    }
};

// A closed diffuse cube [0, 1]^3 of albedo a seen from its centre (every ray hits a wall), with a
// small lamp under its ceiling if `lamp`; material 0 is the walls' (diffuse), material 1 a mirror
// that no surface uses (for vertices made by hand) unless `mirrorWall`: then the wall z = 1, the
// one the camera looks at, is that mirror.
inline ps::Scene closedBox(float albedo, int maxDepth, bool lamp, int resolution = 4, bool mirrorWall = false) {
    const std::string a = std::to_string(albedo);
    std::string text = "camera eye 0.5 0.5 0.5  target 0.5 0.5 1  up 0 1 0  fov 60  resolution " +
                       std::to_string(resolution) + " " + std::to_string(resolution) + "\n" +
                       "material w diffuse albedo " + a + " " + a + " " + a + "\n" +
                       "material m mirror albedo 1 1 1\n"
                       "quad 0 0 0  1 0 0  1 0 1  0 0 1  material w\n"  // floor (y = 0)
                       "quad 0 1 0  0 1 1  1 1 1  1 1 0  material w\n"  // ceiling (y = 1)
                       "quad 0 0 0  0 0 1  0 1 1  0 1 0  material w\n"  // x = 0
                       "quad 1 0 0  1 1 0  1 1 1  1 0 1  material w\n"  // x = 1
                       "quad 0 0 0  0 1 0  1 1 0  1 0 0  material w\n"  // z = 0
                       "quad 0 0 1  1 0 1  1 1 1  0 1 1  material " +
                       (mirrorWall ? "m" : "w") + "\n";  // z = 1
    if (lamp) text += "quad 0.45 0.999 0.45  0.55 0.999 0.45  0.55 0.999 0.55  0.45 0.999 0.55  emission 4 4 4\n";
    text += "render maxdepth " + std::to_string(maxDepth) + "\n";
    return ps::parseScene(text, "closed-box.scene");
}

}  // namespace lesson10
