// Lesson 13, graded: what a merge adds (Eq. 13.3), against brute force. A light pass of 256 light
// subpaths on the open box and the pool (area, point and background lights, mirror, glass, Phong),
// then random camera subpaths: at every camera vertex that can merge, the merges mergeAtVertex
// reports must be exactly the stored light vertices (the merge's own rule, Eq. 13.7: not a
// subpath's first vertex, on a surface, not specular) within distance r of it whose merged path
// has at most maxdepth bounces and whose BSDF value is not black, each once, found by a loop over
// every light vertex of the pass; each merge's unweighted value must be lesson 8's density
// estimate of it, computed here from the two subpaths; what mergeAtVertex returns must be the sum
// of the reported values times their weights; and in vcm-ppm every weight is 1.
#include <algorithm>
#include <map>
#include "lesson13.h"

using namespace lesson13;

namespace {

// Camera subpaths per scene. Measured over PATHSPACE_TEST_SEED 0-29 (2026-11-28, lesson 7's subpaths
// surviving by the material, Eq. 7.1a): 490-784 merges on the open box (the fewest of the three
// runs), well above the 300 checked below; 600 subpaths gave 237-394 there once the subpaths
// ended from their first bounce on.
constexpr int kSamples = 1200;

void checkScene(const std::string& file, ps::VcmMode mode, uint64_t seed) {
    const ps::Scene scene = loadSceneAt(file, 16, 16);
    const int n = scene.camera.width() * scene.camera.height();
    const double r = 0.05 * double(scene.radius);
    const float r2 = float(r * r);
    LightPass pass;
    traceLightPass(scene, n, r, mode, ps::Heuristic::Power, seed, pass);
    ps::Subpath camera;
    ps::MergeSums cameraSums;
    int vertices = 0, merges = 0, missing = 0, extra = 0, twice = 0, wrongValue = 0, wrongSum = 0, wrongWeight = 0;
    std::string firstProblem;
    auto problem = [&](const std::string& what) {
        if (firstProblem.empty()) firstProblem = what;
    };
    const double normalisation = 1.0 / (3.14159265358979323846 * r * r * double(n));
    for (int i = 0; i < kSamples; ++i) {
        ps::Rng rng(seed + 1, uint64_t(i));
        const Vec2 raster(rng.uniform() * float(scene.camera.width()), rng.uniform() * float(scene.camera.height()));
        ps::cameraSubpath(scene, rng, raster, scene.settings.maxDepth, ps::Heuristic::Power, camera);
        ps::mergeSums(camera, ps::Heuristic::Power, cameraSums);
        for (int f = 1; f < int(camera.size()); ++f) {
            const PathVertex& z = camera[size_t(f)];
            if (!z.onSurface() || z.specular) continue;
            ++vertices;
            MergeList list;
            const Color got = ps::mergeAtVertex(scene, camera, cameraSums, f, pass.lights, pass.merge, &list);
            // Brute force: every light vertex of the pass.
            std::map<std::pair<uint32_t, uint32_t>, Color> expected;
            const ps::Material& m = scene.materials[size_t(z.sp.material)];
            const Vec3 wo = ps::direction(z, camera[size_t(f) - 1]);
            for (uint32_t p = 0; p < uint32_t(pass.lights.paths()); ++p) {
                const PathVertex* y = pass.lights.subpath(p);
                for (int e = 1; e < pass.lights.length(p); ++e) {
                    const PathVertex& v = y[e];
                    if (!v.onSurface() || v.specular) continue;
                    if (ps::photonDistance2(v.p(), z.p()) > r2) continue;
                    if (e + f - 1 > scene.settings.maxDepth) continue;
                    const Color fs = ps::evalBSDF(m, z.sp.n, wo, ps::direction(v, y[e - 1]));
                    if (ps::isBlack(fs)) continue;
                    expected[{p, uint32_t(e)}] = v.beta * fs * z.beta * float(normalisation);
                }
            }
            std::map<std::pair<uint32_t, uint32_t>, int> seen;
            Color sum(0.0f);
            for (const Merge& mg : list.merges) {
                const std::pair<uint32_t, uint32_t> key{mg.light.path, mg.light.index};
                ++merges;
                if (++seen[key] == 2) {
                    ++twice;
                    problem("light vertex " + std::to_string(key.second) + " of light subpath " +
                            std::to_string(key.first) + " merged twice at camera vertex " + std::to_string(f));
                }
                sum += mg.unweighted * mg.weight;
                if (mode == ps::VcmMode::Ppm && mg.weight != 1.0f) {
                    ++wrongWeight;
                    problem("vcm-ppm: a merge with weight " + num(mg.weight) + " (expected 1: no MIS)");
                }
                const auto it = expected.find(key);
                if (it == expected.end()) {
                    ++extra;
                    const PathVertex& v = pass.lights.vertex(mg.light);
                    problem("a merge with light vertex " + std::to_string(key.second) + " of light subpath " +
                            std::to_string(key.first) + " at distance " +
                            num(std::sqrt(ps::photonDistance2(v.p(), z.p()))) + " (r = " + num(r) +
                            "), merged path of " + std::to_string(key.second + f + 1) + " vertices, maxdepth " +
                            std::to_string(scene.settings.maxDepth) + ", specular " + (v.specular ? "yes" : "no") +
                            ": not one of the merges expected");
                    continue;
                }
                const Color& want = it->second;
                for (int c = 0; c < 3; ++c)
                    if (std::abs(mg.unweighted[c] - want[c]) > 1e-4f * std::abs(want[c]) + 1e-12f) {
                        ++wrongValue;
                        problem("merge with light vertex " + std::to_string(key.second) + " at camera vertex " +
                                std::to_string(f) + ": expected the unweighted value " + str(want) + ", got " +
                                str(mg.unweighted) + " (ratio " + num(mg.unweighted[c] / want[c]) + ")");
                        break;
                    }
            }
            for (const auto& [key, value] : expected)
                if (!seen.count(key)) {
                    ++missing;
                    problem("light vertex " + std::to_string(key.second) + " of light subpath " +
                            std::to_string(key.first) + " lies within r of camera vertex " + std::to_string(f) +
                            " and was not merged");
                }
            for (int c = 0; c < 3; ++c)
                if (std::abs(got[c] - sum[c]) > 1e-4f * std::abs(sum[c]) + 1e-12f) {
                    ++wrongSum;
                    problem("camera vertex " + std::to_string(f) + ": returned " + str(got) +
                            ", the reported merges times their weights add up to " + str(sum));
                    break;
                }
        }
    }
    const std::string where = file + (mode == ps::VcmMode::Ppm ? " (vcm-ppm)" : " (vcm)");
    CHECK_MESSAGE(missing + extra + twice + wrongValue + wrongSum + wrongWeight == 0,
                  where << ", r = " << num(r) << ", " << vertices << " camera vertices, " << merges
                        << " merges: " << missing << " missing, " << extra << " not expected, " << twice << " twice, "
                        << wrongValue << " with a wrong value, " << wrongSum
                        << " camera vertices whose sum is not the weighted merges', " << wrongWeight
                        << " wrong weights; first: " << firstProblem);
    CHECK_MESSAGE(merges >= 300, where << ": expected at least 300 merges, got " << merges);
}

}  // namespace

TEST_CASE(
    "a camera vertex merges once with every stored light vertex within r, with lesson 8's density estimate "
    "(brute force) [3 pts]") {
    checkScene("tests/13-vcm/data/open-box.scene", ps::VcmMode::Vcm, ps::testseed::seed(13301));
    checkScene("tests/13-vcm/data/pool.scene", ps::VcmMode::Vcm, ps::testseed::seed(13302));
    checkScene("tests/13-vcm/data/pool.scene", ps::VcmMode::Ppm, ps::testseed::seed(13303));
}
