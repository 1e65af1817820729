// Shared by lesson 13's graded tests: the scenes, a light pass at a chosen radius, joined paths,
// the independent oracle of every technique's density (lesson 6's pdfTechnique, extended by
// merging), the significance level.
#pragma once
#include "alpha.h"
#include <doctest/doctest.h>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>
#include "../08-photon-mapping/lesson08.h"
#include "13-vcm/vcm.h"
#include "format.h"
#include "lesson_files.h"
#include "render_helpers.h"
#include "scene_loader.h"
#include "seed.h"
#include "statistics.h"

namespace lesson13 {

using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;

using ps::Color;
using ps::PathVertex;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;

// Statistical tests in this suite (every other check is exact or a stated bound):
//   vcm-ppm against lesson 8's progressive photon mapping at the same radius (z-test)    -> 1
//   vcm on the caustic seen through glass: its mean against the reference (a bias
//   bound plus the noise at this level)                                                 -> 1
// m = 2; each runs at the Sidak level alpha' = 1 - (1 - a_L)^(1/2), where a_L is the lesson's
// share of the whole course's 1 % (tests/support/alpha.h).
constexpr int kStatisticalTests = 2;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }
// The two-sided normal quantile of alpha(): |z| above it fails (lesson 8's helper).
inline double zCritical() { return lesson08::zCriticalAt(alpha()); }

inline double exponentOf(ps::Heuristic h) { return h == ps::Heuristic::Power ? 2.0 : 1.0; }
inline const char* nameOf(ps::Heuristic h) { return h == ps::Heuristic::Power ? "power" : "balance"; }

// ---- a light pass at a chosen radius ----

// Light subpaths of one iteration (the plumbing's light pass), with the tree, and the merging
// options for radius r and these N light paths.
struct LightPass {
    ps::LightVertices lights;
    ps::MergeOptions merge;
};
inline void traceLightPass(const ps::Scene& scene, int lightPaths, double radius, ps::VcmMode mode, ps::Heuristic h,
                           uint64_t seed, LightPass& pass) {
    ps::SampleStats stats;
    ps::traceLightSubpaths(scene, lightPaths, h, seed, 0, pass.lights, stats);
    ps::buildLightVertexTree(pass.lights);
    pass.merge.mode = mode;
    pass.merge.heuristic = h;
    pass.merge.radius = radius;
    pass.merge.lightPaths = lightPaths;
    pass.merge.maxDepth = scene.settings.maxDepth;
}

// Every merge mergeAtVertex reports.
struct Merge {
    ps::LightVertexRef light;
    int f = 0;
    Color unweighted;
    float weight = 0.0f;
};
struct MergeList : ps::MergeRecorder {
    std::vector<Merge> merges;
    void add(const ps::LightVertexRef& light, int f, const Color& unweighted, float weight) override {
        merges.push_back({light, f, unweighted, weight});
    }
};

// ---- joined paths and the oracle ----

// y_0 .. y_{s-1} z_{t-1} .. z_0 as a lesson 6 path (x_0 on the light, x_{n-1} the camera).
inline ps::Path joinPath(const PathVertex* y, int s, const PathVertex* z, int t) {
    ps::Path x;
    for (int i = 0; i < s; ++i) x.push_back(y[i]);
    for (int i = t - 1; i >= 0; --i) x.push_back(z[i]);
    return x;
}

// The path a merge of light vertex y_e with camera vertex z_f stands for (README, section 1.5): the
// light side's vertices y_0 .. y_e, the camera side's z_f .. z_0 moved by y_e - z_f so that z_f
// lands on y_e (a pinhole's densities depend on directions only, so the camera side's densities
// are its own), and at the merge vertex z_f's material and normal. Every technique's density of
// this path is then the merged path's: the light side's from y's geometry, the camera side's from
// z's, and the junction's from both. Only where y_e and z_f lie on the same surface (same normal
// and material): false otherwise.
inline bool mergedPath(const PathVertex* y, int e, const PathVertex* z, int f, ps::Path& x) {
    const PathVertex& ye = y[e];
    const PathVertex& zf = z[f];
    if (ye.sp.material != zf.sp.material || glm::dot(ye.sp.n, zf.sp.n) < 0.999999f) return false;
    const Vec3 delta = ye.p() - zf.p();
    x.clear();
    for (int i = 0; i < e; ++i) x.push_back(y[i]);
    for (int i = f; i >= 0; --i) {
        PathVertex v = z[i];
        v.sp.p = i == f ? ye.p() : v.sp.p + delta;
        x.push_back(v);
    }
    return true;
}

// Whether a merge can happen at x_j of a path of n vertices (the test's own Eq. 13.7): an inner
// vertex on a surface that is not specular.
inline bool mergesAt(const ps::Path& x, int j) {
    const int n = int(x.size());
    return j >= 1 && j <= n - 2 && x[size_t(j)].onSurface() && !x[size_t(j)].specular;
}

// The light subpath's density of x_0 itself: P(l) times the area density (the background's:
// per solid angle), from the framework's light.
inline double lightOriginDensity(const ps::Scene& scene, const PathVertex& v) {
    const int l = v.sp.light;
    if (l < 0) return 0.0;
    const ps::EmissionPdf e = ps::pdfEmission(scene, l, v.sp.n, v.sp.n);
    return double(scene.lightSelectionProb(l)) * (v.infinite ? e.pdfW : e.pdfA);
}

// The densities of every technique that can make the path x (Eq. 13.4-13.7), each with its sample
// count folded in: the connections s' = 0 .. n with lesson 6's pdfTechnique (n_VC = 1), and the
// merges at every x_j that can merge, eta P_L(j) P_E(j) (Eq. 13.2, 13.5), where
//   P_L(j) = prod_{i <= j} p_L(x_i): lesson 6's density of the path x_0 .. x_j joined straight to
//            the camera by technique (j + 1, 1), divided by the camera's point density;
//   P_E(j) = prod_{i >= j} p_E(x_i): lesson 6's density of x_0 x_j .. x_{n-1} under technique
//            (1, n - j), divided by x_0's own density.
// Nothing here is lesson 13's code: an independent oracle of Eq. 13.6.
struct Technique {
    bool merge = false;  // a merge at x_j, else the connection s' = j
    int j = 0;
    double density = 0.0;
};
inline std::vector<Technique> oracleTechniques(const ps::Scene& scene, const ps::Path& x, double eta,
                                               bool connections) {
    std::vector<Technique> out;
    const int n = int(x.size());
    if (connections)
        for (int s = 0; s <= n; ++s) out.push_back({false, s, ps::pdfTechnique(scene, x, s)});
    const double origin = lightOriginDensity(scene, x[0]);
    const PathVertex& camera = x[size_t(n - 1)];
    for (int j = 1; j <= n - 2; ++j) {
        if (!mergesAt(x, j)) continue;
        ps::Path prefix(x.begin(), x.begin() + j + 1);
        prefix.push_back(camera);
        const double pL = ps::pdfTechnique(scene, prefix, j + 1) / double(scene.camera.pdfPoint());
        ps::Path suffix = {x[0]};
        suffix.insert(suffix.end(), x.begin() + j, x.end());
        const double pE = origin > 0.0 ? ps::pdfTechnique(scene, suffix, 1) / origin : 0.0;
        out.push_back({true, j, eta * pL * pE});
    }
    return out;
}

// The oracle's weight of technique `which` (Eq. 13.4): (n_T p_T)^b / sum over the techniques.
inline double oracleWeight(const std::vector<Technique>& ts, bool merge, int j, double b) {
    double sum = 0.0, mine = 0.0;
    for (const Technique& t : ts) {
        const double q = std::pow(t.density, b);
        sum += q;
        if (t.merge == merge && t.j == j) mine = q;
    }
    return sum > 0.0 ? mine / sum : 0.0;
}

inline std::string describe(const ps::Path& x) {
    std::ostringstream o;
    for (size_t i = 0; i < x.size(); ++i) {
        const PathVertex& v = x[i];
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

}  // namespace lesson13
