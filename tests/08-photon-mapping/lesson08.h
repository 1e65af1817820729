// Shared by lesson 8's graded tests: photon sets with clusters and duplicates, brute-force
// searches, the mirror scene with known caustic paths, the significance level.
#pragma once
#include "alpha.h"
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>
#include "08-photon-mapping/photonmap.h"
#include "format.h"
#include "lesson_files.h"
#include "render_helpers.h"
#include "scene_loader.h"
#include "seed.h"
#include "statistics.h"

namespace lesson08 {

using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;

using ps::Color;
using ps::Photon;
using ps::PhotonMap;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;

// Statistical tests in this suite (every other check is exact or a stated bound):
//   photon counts of the mirror scene: caustic map, global map (binomial, as z-tests)   -> 2
//   the flux stored on the floor against the analytic integral I * Omega (z-test)       -> 1
//   radiance estimates of a linear irradiance, box, cone and Gaussian (t-tests)         -> 3
//   the box filter's bias on a quadratic irradiance (t-test)                           -> 1
//   pm against the path-traced Cornell box (a bias bound plus the noise at this level)  -> 1
//   pm-ic against the path-traced Cornell box (the same)                                -> 1
//   a new cache record's E and R at five points (Welch t-tests, Bonferroni inside)      -> 1
//   ppm on the Cornell box: the lamp's pixels (a bound plus the noise at this level)    -> 1
//   pm's caustic on the Cornell spheres' floor (a bound plus the noise at this level)   -> 1
// m = 12 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %: a correct implementation fails the whole graded suite by
// bad luck in fewer than 1 run in 100).
constexpr int kStatisticalTests = 12;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }
// The two-sided normal quantile of level a: |z| above it fails.
inline double zCriticalAt(double a) {
    double lo = 0.0, hi = 20.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (ps::stats::normalTwoSided(mid) > a ? lo : hi) = mid;
    }
    return hi;
}
// The two-sided normal quantile of alpha().
inline double zCritical() { return zCriticalAt(alpha()); }

// A point uniform in the unit cube (numbers drawn x, y, z in this order).
inline Vec3 uniform3(ps::Rng& rng) {
    const float x = rng.uniform(), y = rng.uniform(), z = rng.uniform();
    return Vec3(x, y, z);
}

// A point of the layer z = 0.5 of hardPhotonSet.
inline Vec3 onLayer(ps::Rng& rng) {
    const float x = rng.uniform(), y = rng.uniform();
    return Vec3(x, y, 0.5f);
}

// A photon at p with unit power, arriving from straight above.
inline Photon photonAt(const Vec3& p) {
    Photon ph;
    ph.p = p;
    ph.power = Color(1.0f);
    ph.setWLight(Vec3(0, 1, 0));
    return ph;
}

// 10^4 photons that a kd-tree finds hard: five tight Gaussian clusters, a uniform cloud, a
// flat layer (every photon at z = 0.5), and exact duplicates (40 copies of each of 25 points).
inline std::vector<Photon> hardPhotonSet(uint64_t seed, int n = 10000) {
    ps::Rng rng(seed);
    std::vector<Photon> out;
    const Vec3 centres[5] = {
        {0.2f, 0.2f, 0.2f}, {0.8f, 0.3f, 0.6f}, {0.5f, 0.9f, 0.1f}, {0.1f, 0.7f, 0.9f}, {0.6f, 0.5f, 0.5f}};
    auto gauss = [&]() {
        const float u1 = std::max(rng.uniform(), 1e-7f), u2 = rng.uniform();
        return std::sqrt(-2.0f * std::log(u1)) * std::cos(2.0f * ps::kPi * u2);
    };
    const int duplicates = n / 10, layer = n / 10, clusters = n * 4 / 10;
    for (int i = 0; i < clusters; ++i) {
        const Vec3& c = centres[i % 5];
        out.push_back(photonAt(c + 0.01f * Vec3{gauss(), gauss(), gauss()}));
    }
    for (int i = 0; i < layer; ++i) out.push_back(photonAt(onLayer(rng)));
    for (int i = 0; i < duplicates; ++i) {
        const int which = i % 25;
        out.push_back(photonAt(Vec3(0.04f * float(which), 0.5f, 0.3f + 0.02f * float(which % 5))));
    }
    while (int(out.size()) < n) out.push_back(photonAt(uniform3(rng)));
    // Shuffle (Fisher-Yates with the same generator), so the input is in no useful order.
    for (size_t i = out.size() - 1; i > 0; --i) std::swap(out[i], out[size_t(rng.uniform() * float(i + 1)) % (i + 1)]);
    return out;
}

// Brute force: the squared distances from x of every photon of the map (nodes 1 .. n), computed
// with photonDistance2 as the tree does.
inline std::vector<float> allDistances(const PhotonMap& map, const Vec3& x) {
    std::vector<float> d;
    for (size_t i = 1; i <= map.size(); ++i) d.push_back(ps::photonDistance2(map.nodes[i].p, x));
    return d;
}

// The mirror scene (tests/08-photon-mapping/data/mirror-floor.scene): a point light of
// intensity I at height 1 above a diffuse floor (grey albedo 0.5, 4 x 4, y = 0), a mirror
// (albedo 0.8) of 1 x 1 at height 2 facing down. Every photon the mirror reflects lands on the
// floor (the footprint of the mirror seen from the light's image at height 3 is 3 x 3).
constexpr double kIntensity = 10.0;
constexpr double kFloorHalf = 2.0, kMirrorHalf = 0.5, kLightToFloor = 1.0, kLightToMirror = 1.0;
constexpr double kFloorAlbedo = 0.5, kMirrorAlbedo = 0.8;
// The solid angle of a square of half-side a seen from distance d on its axis.
inline double squareSolidAngle(double a, double d) { return 4.0 * std::asin(a * a / (a * a + d * d)); }

// The pixels that see a light (any ray of a 6 x 6 grid over the pixel hits an emitter first):
// on its edge a pixel is 100 times brighter in some samples than in others, noise that a few
// iterations cannot average and that says nothing about photon mapping. Row-major.
inline std::vector<bool> pixelsSeeingLights(const ps::Scene& scene) {
    return ps::testrender::pixelsWhere(scene, false,
                                       [](bool hit, const ps::SurfacePoint& sp) { return hit && sp.light >= 0; });
}

}  // namespace lesson08
