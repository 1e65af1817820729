// Lesson 13, graded: the MIS weights of connections and merges are exactly the balance / power
// heuristic of every technique's density, with sample counts (Eq. 13.4-13.11), against an oracle
// that is not lesson 13's code: lesson 6's pdfTechnique for the connections, and for a merge at
// x_j the density eta P_L(j) P_E(j) built from pdfTechnique as well (lesson13.h). On scenes with
// an area light, a point light and a background light, a mirror, a glass sphere and a flat glass
// surface of index 1.6 over the floor (the "pool", where the refraction's eta^2 does not cancel)
// and a Phong wall: every valid connection of random camera subpaths with a light subpath of a
// light pass (lesson 7's connect, your misWeightConnection with your mergeTerms) and every merge
// your mergeAtVertex makes (the path it stands for, lesson13.h's mergedPath) must have the
// oracle's weight to a relative 1e-3 (+ 1e-6 absolute; the densities are floats, the weights of
// long paths through glass products of a dozen of them), for vcm (connections and merges) and
// vcm-bpm (merges only), balance and power.
//
// The oracle is lesson 6 AS LINKED (lesson 7's test says why that is right for grading), and
// lesson 7's subpaths and connections as linked.
#include "../07-bidirectional/lesson07.h"
#include "lesson13.h"

using namespace lesson13;

namespace {

// Camera subpaths per scene and heuristic. The rarest count checked below, merges on paths from
// the open box's background, was 19-104 over PATHSPACE_TEST_SEED 0-19 with 1000 once lesson 7's
// subpaths ended from their first bounce (Eq. 7.1a), below its bound of 20 in one seed in ten;
// with 2000, 40-208 (2026-11-28).
constexpr int kSamples = 2000;
constexpr double kRelTol = 1e-3, kAbsTol = 1e-6;
constexpr double kRadius = 0.05;  // r as a fraction of the scene's bounding radius: eta p_L is about 1 here

struct Worst {
    double error = -1.0;
    std::string what;
    double student = 0.0, oracle = 0.0;
    void offer(double s, double o, const std::string& w) {
        const double tol = kRelTol * o + kAbsTol;
        const double e = std::isfinite(s) ? std::abs(s - o) / tol : 1e30;
        if (e > error) {
            error = e;
            what = w;
            student = s;
            oracle = o;
        }
    }
};

struct Counts {
    int connections = 0, merges = 0, specular = 0, point = 0, background = 0, shared = 0, otherSurface = 0;
};

void checkScene(const std::string& file, ps::VcmMode mode, ps::Heuristic h, uint64_t seed) {
    const ps::Scene scene = loadSceneAt(file, 16, 16);
    const int n = scene.camera.width() * scene.camera.height();
    const double r = kRadius * double(scene.radius);
    const double eta = double(n) * 3.14159265358979323846 * r * r;
    const double b = exponentOf(h);
    const bool vcm = mode == ps::VcmMode::Vcm;
    LightPass pass;
    traceLightPass(scene, n, r, mode, h, seed, pass);
    Worst connection, merge;
    Counts count;
    ps::Subpath camera;
    ps::MergeSums cameraSums;
    const int maxDepth = scene.settings.maxDepth;
    for (int i = 0; i < kSamples; ++i) {
        ps::Rng rng(seed + 1, uint64_t(i));
        const Vec2 raster(rng.uniform() * float(scene.camera.width()), rng.uniform() * float(scene.camera.height()));
        ps::cameraSubpath(scene, rng, raster, maxDepth, h, camera);
        ps::mergeSums(camera, h, cameraSums);
        // The connections with one light subpath of the pass.
        const uint32_t li = uint32_t(i % n);
        const ps::Subpath light(pass.lights.subpath(li), pass.lights.subpath(li) + pass.lights.length(li));
        const ps::MergeSums lightSums(pass.lights.subpathSums(li),
                                      pass.lights.subpathSums(li) + pass.lights.length(li));
        if (vcm)
            lesson07::forEachConnection(scene, light, camera, rng, [&](const ps::Connection& c, int s, int t) {
                const PathVertex* y = s == 1 ? &c.sampledLight : light.data();
                const float w7 = ps::misWeightRecursive(y, s, camera.data(), t, c.rev, h);
                const double m =
                    ps::mergeTerms({y, lightSums.data(), s}, {camera.data(), cameraSums.data(), t}, c.rev, h);
                ps::VcmMis mis;
                mis.heuristic = h;
                mis.eta = eta;
                const float w = ps::misWeightConnection(w7, m, mis);
                const ps::Path x = joinPath(y, s, camera.data(), t);
                const std::vector<Technique> ts = oracleTechniques(scene, x, eta, true);
                if (!(ts[size_t(s)].density > 0.0)) return;  // lesson 7's test counts these
                ++count.connections;
                connection.offer(
                    w, oracleWeight(ts, false, s, b),
                    describe(x) + " made by connection (" + std::to_string(s) + ", " + std::to_string(t) + ")");
            });
        // The merges at every camera vertex.
        MergeList list;
        for (int f = 1; f < int(camera.size()); ++f)
            if (ps::mergeable(camera.data(), f))
                ps::mergeAtVertex(scene, camera, cameraSums, f, pass.lights, pass.merge, &list);
        for (const Merge& mg : list.merges) {
            const PathVertex* lp = pass.lights.subpath(mg.light.path);
            const int e = int(mg.light.index);
            ps::Path x;
            if (!mergedPath(lp, e, camera.data(), mg.f, x)) {
                ++count.otherSurface;
                continue;
            }
            const std::vector<Technique> ts = oracleTechniques(scene, x, eta, vcm);
            const double o = oracleWeight(ts, true, e, b);
            ++count.merges;
            bool spec = false;
            for (const PathVertex& v : x) spec = spec || v.specular;
            count.specular += spec;
            count.point += x[0].pointLight;
            count.background += x[0].infinite;
            count.shared += o > 0.05 && o < 0.95;
            merge.offer(mg.weight, o,
                        describe(x) + " made by the merge at vertex " + std::to_string(e) + " (light vertex " +
                            std::to_string(e) + " of its subpath, camera vertex " + std::to_string(mg.f) + ")");
        }
    }
    const std::string where = file + " (" + (vcm ? "vcm" : "vcm-bpm") + ", " + nameOf(h) + " heuristic)";
    const std::string hints =
        " Hints: a merge's density is the connection's at the same vertex times eta = N pi r^2 (both to the power "
        "b) times the light side's density of the merge vertex (Eq. 13.2, 13.5); D_i carries the reverse density "
        "to the power b (Eq. 13.8); the last vertex of a camera subpath that hit a light is not a merge "
        "(Eq. 13.9).";
    if (vcm)
        CHECK_MESSAGE(connection.error <= 1.0,
                      where << ": a connection's weight among connections and merges: expected the oracle's "
                               "(n_T p_T)^b / sum (relative 1e-3), worst on "
                            << connection.what << ": expected " << num(connection.oracle, 7) << ", got "
                            << num(connection.student, 7) << "." << hints);
    CHECK_MESSAGE(merge.error <= 1.0, where << ": a merge's weight: expected the oracle's (n_T p_T)^b / sum "
                                               "(relative 1e-3), worst on "
                                            << merge.what << ": expected " << num(merge.oracle, 7) << ", got "
                                            << num(merge.student, 7) << "." << hints);
    if (vcm)
        CHECK_MESSAGE(count.connections >= 200,
                      where << ": expected at least 200 valid connections, got " << count.connections);
    CHECK_MESSAGE(count.merges >= 200, where << ": expected at least 200 merges from " << kSamples
                                             << " camera subpaths at r = " << num(r) << ", got " << count.merges);
    CHECK_MESSAGE(count.specular >= 20, where << ": expected at least 20 merges on paths through the mirror or "
                                                 "the glass, got "
                                              << count.specular);
    CHECK_MESSAGE(count.point >= 20,
                  where << ": expected at least 20 merges on paths from the point light, got " << count.point);
    if (scene.background >= 0)
        CHECK_MESSAGE(count.background >= 20,
                      where << ": expected at least 20 merges on paths from the background, got " << count.background);
    // A merge across an edge (the light vertex on one wall, the camera vertex on another) has no
    // path of its own to compare with (lesson13.h, mergedPath); the test needs most merges on one
    // surface.
    CHECK_MESSAGE(count.otherSurface <= count.merges / 5, where << ": " << count.otherSurface
                                                                << " merges joined vertices of two different surfaces, "
                                                                << count.merges << " one surface");
    // The radius is chosen so that merges and connections share many paths; a test that saw only
    // weights near 0 and 1 could not see eta.
    CHECK_MESSAGE(count.shared >= 20, where << ": expected at least 20 merges whose weight lies between 0.05 and "
                                               "0.95, got "
                                            << count.shared);
}

}  // namespace

TEST_CASE(
    "weights of connections and merges equal the heuristic of lesson 6's path pdfs extended by merging, through "
    "mirror and glass, from area, point and background lights [5 pts]") {
    for (const ps::Heuristic h : {ps::Heuristic::Balance, ps::Heuristic::Power}) {
        checkScene("tests/13-vcm/data/open-box.scene", ps::VcmMode::Vcm, h, ps::testseed::seed(13101));
        checkScene("tests/13-vcm/data/pool.scene", ps::VcmMode::Vcm, h, ps::testseed::seed(13102));
    }
}

TEST_CASE("bidirectional photon mapping: merges weighted against merges alone equal the oracle's [2 pts]") {
    for (const ps::Heuristic h : {ps::Heuristic::Balance, ps::Heuristic::Power}) {
        checkScene("tests/13-vcm/data/open-box.scene", ps::VcmMode::Bpm, h, ps::testseed::seed(13103));
        checkScene("tests/13-vcm/data/pool.scene", ps::VcmMode::Bpm, h, ps::testseed::seed(13104));
    }
}
