// Shared by lesson 3's graded tests: the analytic scenes (closed furnace, point light in a
// sphere), many samples of one estimator's Li, renders through the registered integrators,
// the significance level and printing helpers.
#pragma once
#include <doctest/doctest.h>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include "03-path-tracing/pathtracer.h"
#include "image.h"
#include "render.h"
#include "scene_loader.h"
#include "render_helpers.h"
#include "statistics.h"
#include "alpha.h"
#include "lesson_files.h"
#include "seed.h"

namespace lesson03 {

using ps::testfiles::loadSceneAt;
using ps::testfiles::readText;
using ps::testfiles::sourcePath;

using ps::Color;
using ps::Vec2;
using ps::Vec3;

// Statistical tests in this suite (every other check is exact):
//   t-tests: closed furnace, 3 albedos x 3 estimators                              ->  9
//            closed furnace with albedo 1, pt-nee and pt                            ->  2
//            point light in a sphere, 3 radii x 2 estimators                        ->  6
//            MIS on a walk with its own direction sampler (test_extensions.cpp)     ->  1
//   z-tests: the Cornell box, 3 estimators against the stored reference             ->  3
// m = 21 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %: a correct implementation fails the whole graded suite by
// bad luck in fewer than 1 run in 100).
constexpr int kStatisticalTests = 21;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

// The three estimators: algorithm name and function.
struct Estimator {
    std::string name;
    ps::Color (*Li)(const ps::Scene&, const ps::Ray&, ps::Rng&, int);
};
inline const std::vector<Estimator>& estimators() {
    static const std::vector<Estimator> e = {{"pt-bsdf (LiRandomWalk)", ps::LiRandomWalk},
                                             {"pt-nee (LiNextEvent)", ps::LiNextEvent},
                                             {"pt (LiMIS)", ps::LiMIS}};
    return e;
}

inline std::string num(double x) {
    std::ostringstream s;
    s.precision(10);
    s << x;
    return s.str();
}
inline std::string str(const Vec3& v) {
    std::ostringstream s;
    s.precision(9);
    s << "(" << v.x << ", " << v.y << ", " << v.z << ")";
    return s.str();
}
using ps::testrender::sum;

// A closed furnace with diffuse albedo a and emission Le (grey): the camera at the centre of a
// closed enclosure whose walls emit Le inwards and reflect with albedo a. The cube is
// scenes/furnace.scene; the sphere tests/03-path-tracing/data/furnace-sphere.scene (an
// icosphere: in the cube next-event estimation has infinite variance, see that file).
enum class Enclosure { Cube, Sphere };
inline ps::Scene furnace(Enclosure shape, float albedo, float Le) {
    const std::string path = sourcePath(shape == Enclosure::Cube ? "scenes/furnace.scene"
                                                                 : "tests/03-path-tracing/data/furnace-sphere.scene");
    std::string s = ps::scenetext::replaceAll(readText(path), "albedo 0.5 0.5 0.5",
                                              "albedo " + num(albedo) + " " + num(albedo) + " " + num(albedo));
    s = ps::scenetext::replaceAll(s, "emission 1 1 1", "emission " + num(Le) + " " + num(Le) + " " + num(Le));
    return ps::parseScene(s, path);
}

// Eq. 3.8: the closed furnace truncated at D bounces, L = Le (1 - a^(D+1)) / (1 - a).
inline double furnaceRadiance(double a, double Le, int D) {
    return a == 1.0 ? Le * (D + 1) : Le * (1.0 - std::pow(a, D + 1)) / (1.0 - a);
}

// scenes/point-in-sphere.scene scaled by R: a point light of intensity I = R^2 at the centre of
// a diffuse sphere of radius R and albedo a, the camera at (0, 0, -R/2).
inline ps::Scene pointInSphere(float R, float albedo) {
    std::ostringstream s;
    s << "camera eye 0 0 " << num(-0.5 * R) << "  target 0 0 " << num(R) << "  fov 90  resolution 1 1\n"
      << "material wall diffuse albedo " << num(albedo) << " " << num(albedo) << " " << num(albedo) << "\n"
      << "sphere center 0 0 0  radius " << num(R) << "  material wall\n"
      << "pointlight position 0 0 0  intensity " << num(double(R) * R) << " " << num(double(R) * R) << " "
      << num(double(R) * R) << "\n";
    return ps::parseScene(s.str(), "point-in-sphere, R = " + num(R) + " (lesson03.h)");
}

// Eq. 3.9: L = a I / (pi R^2) (1 - a^D) / (1 - a); with I = R^2 it does not depend on R.
inline double pointInSphereRadiance(double a, double I, double R, int D) {
    return a * I / (3.14159265358979323846 * R * R) * (1.0 - std::pow(a, D)) / (1.0 - a);
}

// n samples of Li (summed over R, G, B) along rays from the camera position in uniformly
// distributed directions, sample i with its own generator taskRng(seed, 0, i).
struct Samples {
    ps::stats::Welford w;
    int bad = 0;
    double min = 1e300, max = -1e300;
};
inline Samples sampleLi(const ps::Scene& scene, const Estimator& e, int maxDepth, int n, uint64_t seed) {
    Samples s;
    for (int i = 0; i < n; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(seed), 0, uint32_t(i));
        const Vec3 d = ps::sampleUniformSphere(rng.uniform2());
        const Color c = e.Li(scene, ps::Ray(scene.camera.position(), d), rng, maxDepth);
        if (!ps::isFinite(c)) {
            ++s.bad;
            continue;
        }
        const double v = sum(c);
        s.w.add(v);
        s.min = std::min(s.min, v);
        s.max = std::max(s.max, v);
    }
    return s;
}

// Renders on one thread (tiny test images: tests/support/render_helpers.h).
using ps::testrender::Render;
using ps::testrender::render;

}  // namespace lesson03
