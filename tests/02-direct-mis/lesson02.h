// Shared by lesson 2's graded tests: scenes at test resolution, renders through the registered
// integrators, the stored reference images, per-plate masks of Veach's scene, the significance
// level, and printing helpers.
#pragma once
#include <doctest/doctest.h>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include "02-direct-mis/direct.h"
#include "image.h"
#include "integrator.h"
#include "metrics.h"
#include "render.h"
#include "scene_loader.h"
#include "render_helpers.h"
#include "statistics.h"
#include "alpha.h"
#include "lesson_files.h"

namespace lesson02 {

using ps::testfiles::loadSceneAt;
using ps::testfiles::readText;
using ps::testfiles::sourcePath;

using ps::Color;
using ps::Vec2;
using ps::Vec3;

// Statistical tests in this suite (every other check is exact or deterministic):
//   t-tests (Lambert's polygon light): 2 points x 6 estimators                    -> 12
//   z-tests (images against the stored reference): 6 estimators                   ->  6
// m = 18 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %). (The relMSE comparison of the
// heuristics is not a hypothesis test: it compares fixed-seed renders whose margins are
// documented in test_plates.cpp.)
constexpr int kStatisticalTests = 18;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

// The estimators of the lesson, by their names in the render command.
inline const std::vector<std::string>& estimators() {
    static const std::vector<std::string> names = {"direct-light", "direct-bsdf", "direct-balance",
                                                   "direct-power", "direct-max",  "direct-onesample"};
    return names;
}

// Renders on ONE thread (tests/support/render_helpers.h says why).
using ps::testrender::Render;
using ps::testrender::render;

// Every test render must be free of NaN and Inf samples.
#define LESSON02_CHECK_FINITE(r)                                                                                \
    CHECK_MESSAGE((r).stats.bad() == 0, (r).algo << ": expected 0 NaN and 0 Inf samples, got " << (r).stats.nan \
                                                 << " NaN and " << (r).stats.inf << " Inf")

// The stored reference images (tests/02-direct-mis/data, README section 4 says how they are made).
inline ps::Image readData(const std::string& name) {
    return ps::readPFM(sourcePath("tests/02-direct-mis/data/" + name));
}

using ps::testrender::sum;

inline std::string str(const Vec3& v) {
    std::ostringstream s;
    s.precision(7);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}

// The plate each pixel shows (0 = back, exponent 10000 ... 3 = front, exponent 10), or -1:
// the material hit by the ray through the pixel's centre.
inline std::vector<int> plateMask(const ps::Scene& scene) {
    const int w = scene.camera.width(), h = scene.camera.height();
    std::vector<int> mask(size_t(w) * h, -1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            ps::Ray ray = scene.camera.generateRay(Vec2(x + 0.5f, y + 0.5f));
            ps::SurfacePoint sp;
            if (!scene.intersect(ray, sp) || sp.material < 0) continue;
            const std::string& name = scene.materials[sp.material].name;
            if (name.size() == 6 && name.compare(0, 5, "plate") == 0) mask[size_t(y) * w + x] = name[5] - '1';
        }
    return mask;
}

// relMSE (Eq. of framework/metrics.h, eps = 0.01) over the pixels of one plate.
inline double plateRelMse(const ps::Image& img, const ps::Image& ref, const std::vector<int>& mask, int plate) {
    double s = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        if (mask[i] != plate) continue;
        for (int c = 0; c < 3; ++c) {
            const double d = double(img.pixels[i][c]) - ref.pixels[i][c], r = ref.pixels[i][c];
            s += d * d / (r * r + ps::kRelMseEpsilon);
            ++n;
        }
    }
    return n ? s / double(n) : 0.0;
}

}  // namespace lesson02
