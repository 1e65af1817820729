// Lesson 7, graded: the MIS weights (Eq. 7.5-7.10). For many random joined paths of the Cornell
// family (every valid connection of random pixel samples), the path is split at every technique
// s' that can sample it (the test's own Eq. 7.7), each split's subpaths rebuilt with their
// pdfFwd / pdfRev and misSum (updateMisSum), its connection's reverse pdfs from connectionPdfs,
// and the weights added up: they must sum to 1 (the weights partition the path's estimate,
// Eq. 7.5), with the full list and the recursive form, and the two forms must agree.
#include "lesson07.h"
#include "seed.h"

using namespace lesson07;

namespace {

const std::vector<std::string> kScenes = {"scenes/cornell-box.scene", "scenes/cornell-spheres.scene",
                                          "scenes/cornell-point-light.scene", "scenes/cornell-background.scene",
                                          "scenes/cornell-glossy.scene"};
constexpr int kSamples = 400;  // pixel samples per scene

struct Checked {
    int paths = 0, worst = -1;
    double worstError = 0.0;
    std::string worstText;
};

template <class Weight>
void checkScene(const std::string& scenePath, ps::Heuristic h, const char* form, Weight weight) {
    const ps::Scene scene = loadSceneAt(scenePath, 16, 16);
    const std::vector<JoinedPath> paths = randomPaths(scene, kSamples, ps::testseed::seed(7001), h);
    CHECK_MESSAGE(paths.size() >= 100, scenePath << ": expected at least 100 valid connections from " << kSamples
                                                 << " pixel samples (subpaths and connect), got " << paths.size());
    double worst = 0.0;
    std::string worstText;
    for (const JoinedPath& j : paths) {
        double total = 0.0;
        std::ostringstream terms;
        for (int sp = 0; sp <= int(j.x.size()); ++sp) {
            if (!samples(j, sp)) continue;
            const Split sp_ = split(scene, j, sp, h);
            const float w = weight(sp_, sp, int(j.x.size()) - sp);
            total += w;
            terms << " w(" << sp << "," << int(j.x.size()) - sp << ") = " << num(w, 6);
        }
        const double err = std::abs(total - 1.0);
        if (!(err <= worst)) {
            worst = std::isfinite(err) ? err : 1e30;
            worstText = describe(j) + ":" + terms.str() + ", sum " + num(total, 7);
        }
    }
    CHECK_MESSAGE(worst <= 1e-5, scenePath << ", " << std::string(h == ps::Heuristic::Power ? "power" : "balance")
                                           << " heuristic, " << std::string(form)
                                           << ": expected the weights of every path's techniques to sum to 1 "
                                              "(+- 1e-5), worst "
                                           << worstText);
}

}  // namespace

TEST_CASE("MIS weights from the full pdf list sum to 1 over the techniques of a path (balance and power) [3 pts]") {
    for (const ps::Heuristic h : {ps::Heuristic::Balance, ps::Heuristic::Power})
        for (const std::string& s : kScenes)
            checkScene(s, h, "misWeightFull", [&](const Split& x, int sp, int tp) {
                return ps::misWeightFull(x.y.data(), sp, x.z.data(), tp, x.rev, h);
            });
    // Eq. 7.7 outside the techniques 0 ... n: no technique s' = -1 or n + 1 samples anything.
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 16, 16);
    const std::vector<JoinedPath> paths = randomPaths(scene, 20, ps::testseed::seed(7003), ps::Heuristic::Balance);
    REQUIRE_MESSAGE(!paths.empty(), "test setup: no joined path");
    const JoinedPath& j = paths.front();
    const int n = int(j.x.size());
    for (int sp : {-1, n + 1})
        CHECK_MESSAGE(!ps::techniqueSamples(j.x.data(), n, sp),
                      describe(j) << ": techniqueSamples(x, " << n << ", " << sp
                                  << "): expected false (s' outside 0 ... " << n << "), got true");
}

TEST_CASE("recursive MIS weights sum to 1 and equal the full-list weights to 1e-5 [3 pts]") {
    for (const ps::Heuristic h : {ps::Heuristic::Balance, ps::Heuristic::Power})
        for (const std::string& s : kScenes) {
            checkScene(s, h, "misWeightRecursive", [&](const Split& x, int sp, int tp) {
                return ps::misWeightRecursive(x.y.data(), sp, x.z.data(), tp, x.rev, h);
            });
            // Both forms on every technique of every path.
            const ps::Scene scene = loadSceneAt(s, 16, 16);
            const std::vector<JoinedPath> paths = randomPaths(scene, kSamples / 3, ps::testseed::seed(7002), h);
            double worst = 0.0;
            std::string where;
            for (const JoinedPath& j : paths)
                for (int sp = 0; sp <= int(j.x.size()); ++sp) {
                    if (!samples(j, sp)) continue;
                    const Split x = split(scene, j, sp, h);
                    const int tp = int(j.x.size()) - sp;
                    const float wf = ps::misWeightFull(x.y.data(), sp, x.z.data(), tp, x.rev, h);
                    const float wr = ps::misWeightRecursive(x.y.data(), sp, x.z.data(), tp, x.rev, h);
                    const double d = std::abs(double(wf) - double(wr));
                    if (!(d <= worst)) {
                        worst = std::isfinite(d) ? d : 1e30;
                        where = describe(j) + ", technique (" + std::to_string(sp) + ", " + std::to_string(tp) +
                                "): full " + num(wf, 7) + ", recursive " + num(wr, 7);
                    }
                }
            CHECK_MESSAGE(worst <= 1e-5,
                          s << ": expected misWeightRecursive = misWeightFull (+- 1e-5), worst at " << where);
        }
    // Eq. 7.9, 7.10 by hand for a camera subpath whose z_0 is a camera model's point (a ray can hit
    // it: t = 0 samples the path, c_0 = 1) and for the pinhole (c_0 = 0): z_0 with pdfRev / pdfFwd
    // = 0.5, then B_2 = r_0^b (c_0 + B_1) with B_1 = 0.
    for (const bool model : {true, false})
        for (const ps::Heuristic h : {ps::Heuristic::Balance, ps::Heuristic::Power}) {
            ps::Subpath z(3);
            z[0].onCamera = model;
            z[0].pinhole = !model;
            for (ps::PathVertex& v : z) v.sp.n = Vec3(0, 0, 1);
            z[0].pdfFwd = 1.0f, z[0].pdfRev = 0.5f;
            z[1].pdfFwd = 2.0f, z[1].pdfRev = 1.0f;
            z[2].pdfFwd = 3.0f, z[2].pdfRev = 1.0f;
            for (size_t i = 0; i < 3; ++i) ps::updateMisSum(z, i, h);
            const double expected = model ? (h == ps::Heuristic::Power ? 0.25 : 0.5) : 0.0;
            CHECK_MESSAGE(std::abs(z[2].misSum - expected) <= 1e-7,
                          "a camera subpath z_0 z_1 z_2, z_0 "
                              << (model ? "a camera model's point (c_0 = 1)" : "the pinhole (c_0 = 0)")
                              << ", r_0 = pdfRev / pdfFwd = 0.5, " << (h == ps::Heuristic::Power ? "power" : "balance")
                              << " heuristic: expected B_2 = r_0^b (c_0 + B_1) = " << expected << ", got "
                              << z[2].misSum);
        }
}
