// Lesson 7, graded: the camera subpath hands each vertex it stores to a visitor (an algorithm that
// works at every camera vertex, merging it with light vertices nearby, say, needs nothing more):
// the visitor sees z_1, z_2, ... in order, each with its densities and misSum already set, the
// subpath is the same as without a visitor, and a visitor that returns false ends the subpath.
#include "lesson07.h"
#include "seed.h"

using namespace lesson07;

TEST_CASE("camera subpath: its visitor sees every vertex once stored, in order, and can end the subpath [1 pt]") {
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 16, 16);
    int checked = 0;
    for (uint32_t i = 0; i < 64; ++i) {
        ps::Rng plainRng = ps::taskRng(ps::testseed::seed(7301), 0, i), seenRng = plainRng, stopRng = plainRng;
        const Vec2 raster(8.5f, 8.5f);
        ps::Subpath plain, seen, stopped;
        ps::cameraSubpath(scene, plainRng, raster, 8, ps::Heuristic::Power, plain);
        std::vector<size_t> sizes;
        std::string wrong;
        ps::cameraSubpath(scene, seenRng, raster, 8, ps::Heuristic::Power, seen, [&](const ps::Subpath& path) {
            sizes.push_back(path.size());
            if (path.size() > plain.size()) {
                wrong = "more vertices than without a visitor";
                return true;
            }
            const ps::PathVertex& v = path.back();
            const ps::PathVertex& want = plain[path.size() - 1];
            if (wrong.empty() && (v.p() != want.p() || v.pdfFwd != want.pdfFwd || v.misSum != want.misSum))
                wrong = "z_" + std::to_string(path.size() - 1) +
                        " is not the vertex the subpath stores there (point, pdfFwd or misSum differ: the visitor "
                        "must see it once stored, densities and misSum set)";
            return true;
        });
        std::vector<size_t> want;
        for (size_t k = 2; k <= plain.size(); ++k) want.push_back(k);
        CHECK_MESSAGE(sizes == want, "pixel sample "
                                         << i << ": the visitor must be called once per stored vertex z_1 .. z_"
                                         << plain.size() - 1 << " (path sizes 2 .. " << plain.size() << "), got "
                                         << sizes.size() << " calls");
        CHECK_MESSAGE(wrong.empty(), "pixel sample " << i << ": " << wrong);
        CHECK_MESSAGE(seen.size() == plain.size(),
                      "pixel sample " << i << ": a visitor that says go on changed the subpath (" << seen.size()
                                      << " vertices instead of " << plain.size() << ")");
        if (plain.size() >= 4) {
            ps::cameraSubpath(scene, stopRng, raster, 8, ps::Heuristic::Power, stopped,
                              [&](const ps::Subpath& path) { return path.size() < 3; });
            CHECK_MESSAGE(stopped.size() == 3, "pixel sample " << i
                                                               << ": a visitor that returns false at z_2 must end the "
                                                                  "subpath there (3 vertices), got "
                                                               << stopped.size());
            ++checked;
        }
    }
    CHECK_MESSAGE(checked >= 10, "only " << checked
                                         << " of 64 camera subpaths of the closed Cornell box had 4 vertices or "
                                            "more (z_0 and at least three hits): is cameraSubpath done?");
}
