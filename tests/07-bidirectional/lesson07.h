// Shared by lesson 7's graded tests: scenes at test resolution, renders, stored references,
// joined paths split at every technique, the significance level.
#pragma once
#include "alpha.h"
#include <doctest/doctest.h>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include "07-bidirectional/bpt.h"
#include "format.h"
#include "lesson_files.h"
#include "image.h"
#include "render.h"
#include "scene_loader.h"
#include "render_helpers.h"
#include "statistics.h"

namespace lesson07 {

using ps::testfiles::loadSceneAt;
using ps::testfiles::readText;
using ps::testfiles::sourcePath;

using ps::Color;
using ps::PathVertex;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;

// Statistical tests in this suite (every other check is exact or a stated bound):
//   per-technique images of path lengths 1-3 on the Cornell box against the path-traced
//   reference restricted to that length: 9 techniques                                   -> 9
//   bpt against path-traced references: Cornell box (bpt and bpt-balance), Cornell spheres,
//   point light, background                                                              -> 5
//   pruned against unpruned renders: point light, spheres                               -> 2
//   subpath lengths against the geometric law of Eq. 7.1a: light and camera subpaths   -> 2
// m = 18 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %: a correct implementation fails the whole graded suite by
// bad luck in fewer than 1 run in 100).
constexpr int kStatisticalTests = 18;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

using ps::testrender::Render;
using ps::testrender::render;

using ps::testrender::sum;
using ps::testrender::total;

// ---- a joined path, split at every technique (the test's own bookkeeping, Eq. 7.5-7.7) ----

// x_0 .. x_{n-1} (light to camera) with the densities of each vertex from the light side (pL)
// and from the camera side (pE), read from the subpaths and the connection's reverse pdfs.
struct JoinedPath {
    std::vector<PathVertex> x;
    std::vector<float> pL, pE;
    int s = 0, t = 0;  // the technique that made it
};

inline JoinedPath join(const PathVertex* y, int s, const PathVertex* z, int t, const ps::ReversePdfs& rev) {
    JoinedPath j;
    j.s = s;
    j.t = t;
    const int n = s + t;
    j.x.resize(size_t(n));
    j.pL.resize(size_t(n));
    j.pE.resize(size_t(n));
    for (int i = 0; i < s; ++i) {
        j.x[size_t(i)] = y[i];
        j.pL[size_t(i)] = y[i].pdfFwd;
        j.pE[size_t(i)] = i == s - 1 ? rev.lightEnd : i == s - 2 ? rev.lightPrev : y[i].pdfRev;
    }
    for (int k = 0; k < t; ++k) {
        const size_t i = size_t(n - 1 - k);
        j.x[i] = z[k];
        j.pE[i] = z[k].pdfFwd;
        j.pL[i] = k == t - 1 ? rev.cameraEnd : k == t - 2 ? rev.cameraPrev : z[k].pdfRev;
    }
    return j;
}

// Whether technique s' can sample the joined path (the test's own copy of Eq. 7.7), and its
// density p_s' = prod_{i<s'} pL[i] prod_{i>=s'} pE[i] (Eq. 7.7) is not 0: a float density that
// underflows to 0 (a Phong lobe of exponent 50 far from its peak gives pdfs near 1e-41) means
// that technique cannot have made the path; its weight is not part of the sum.
inline bool samples(const JoinedPath& j, int sp) {
    const int n = int(j.x.size());
    if (sp >= n) return false;
    if (sp == 0 && j.x[0].pointLight) return false;
    if (sp > 0 && (j.x[size_t(sp - 1)].specular || j.x[size_t(sp)].specular)) return false;
    if (sp == 1 && n == 2 && j.x[0].infinite) return false;
    double p = 1.0;
    for (int i = 0; i < n; ++i) p *= double(i < sp ? j.pL[size_t(i)] : j.pE[size_t(i)]);
    return p > 0.0;
}

// The subpaths of technique s' of the joined path, as the subpath functions would have built
// them (pdfFwd, pdfRev, and misSum through updateMisSum), and the reverse pdfs of its connection.
struct Split {
    ps::Subpath y, z;
    ps::ReversePdfs rev;
};
inline Split split(const ps::Scene& scene, const JoinedPath& j, int sp, ps::Heuristic h) {
    Split out;
    const int n = int(j.x.size());
    for (int i = 0; i < sp; ++i) {
        PathVertex v = j.x[size_t(i)];
        v.pdfFwd = j.pL[size_t(i)];
        v.pdfRev = j.pE[size_t(i)];
        out.y.push_back(v);
        ps::updateMisSum(out.y, out.y.size() - 1, h);
    }
    for (int i = n - 1; i >= sp; --i) {
        PathVertex v = j.x[size_t(i)];
        v.pdfFwd = j.pE[size_t(i)];
        v.pdfRev = j.pL[size_t(i)];
        out.z.push_back(v);
        ps::updateMisSum(out.z, out.z.size() - 1, h);
    }
    out.rev = ps::connectionPdfs(scene, out.y.data(), sp, out.z.data(), n - sp);
    return out;
}

// Every valid connection (s, t) of a light and a camera subpath, as bpt tries them (no pruning; the
// random numbers of s = 1 from rng): fn(c, s, t) for each.
template <class Fn>
void forEachConnection(const ps::Scene& scene, const ps::Subpath& light, const ps::Subpath& camera, ps::Rng& rng,
                       Fn&& fn) {
    for (int t = 1; t <= int(camera.size()); ++t)
        for (int s = 0; s <= std::max(int(light.size()), 1); ++s) {
            if (s + t < 2 || (t == 1 && s == 0) || s + t - 2 > scene.settings.maxDepth) continue;
            if (s > int(light.size()) && !(s == 1 && t >= 2)) continue;
            const float uLight = rng.uniform();  // drawn in this order on every compiler (named variables)
            const Vec2 uPoint = rng.uniform2();
            const ps::Connection c = ps::connect(scene, light, camera, s, t, uLight, uPoint);
            if (c.valid) fn(c, s, t);
        }
}

// Every valid connection of nSamples pixel samples of a scene (random pixels), as joined paths.
inline std::vector<JoinedPath> randomPaths(const ps::Scene& scene, int nSamples, uint64_t seed, ps::Heuristic h) {
    std::vector<JoinedPath> paths;
    ps::Subpath camera, light;
    const int w = scene.camera.width(), ht = scene.camera.height();
    for (int i = 0; i < nSamples; ++i) {
        ps::Rng rng(seed, uint64_t(i));
        const Vec2 raster{rng.uniform() * float(w), rng.uniform() * float(ht)};
        ps::cameraSubpath(scene, rng, raster, scene.settings.maxDepth, h, camera);
        ps::lightSubpath(scene, rng, scene.settings.maxDepth, h, light);
        forEachConnection(scene, light, camera, rng, [&](const ps::Connection& c, int s, int t) {
            paths.push_back(join(s == 1 ? &c.sampledLight : light.data(), s, camera.data(), t, c.rev));
        });
    }
    return paths;
}

inline std::string describe(const JoinedPath& j) {
    std::ostringstream o;
    o << "a path of " << j.x.size() << " vertices made by (s, t) = (" << j.s << ", " << j.t << "): ";
    for (size_t i = 0; i < j.x.size(); ++i) {
        const PathVertex& v = j.x[i];
        o << (i ? " - " : "")
          << (v.pinhole      ? "camera"
              : v.infinite   ? "background"
              : v.pointLight ? "point light"
              : v.specular   ? "specular"
              : v.onLight    ? "area light"
                             : "surface");
    }
    return o.str();
}

}  // namespace lesson07
