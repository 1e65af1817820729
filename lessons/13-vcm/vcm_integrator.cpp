// Lesson 13 — vertex connection and merging, the render command's `vcm` (plumbing: read it,
// nothing to write here), and its special cases as options of the same integrator: `vcm-balance`
// (the balance heuristic), `vcm-bpt` (no merging: lesson 7's bpt, bit for bit), `vcm-bpm`
// (bidirectional photon mapping: merges at every camera vertex, no connections) and `vcm-ppm`
// (progressive photon mapping: one merge at the first non-specular camera vertex, no MIS).
//
// One iteration i (README, section 1.8):
//   1. the light pass: one light subpath per pixel (N = width * height of them, lesson 7's
//      lightSubpath), their merging sums (Eq. 13.8), and lesson 8's kd-tree over the vertices a
//      merge may use (light_vertices.cpp);
//   2. the camera pass: for every pixel a camera subpath through a jittered point of the pixel
//      (lesson 7's cameraSubpath), every connection (s, t) with the pixel's own light subpath
//      (lesson 7's connectSubpaths, t = 1 splatted as in lesson 7), weighted by Eq. 13.10, and at
//      every camera vertex the merges with the light vertices within r_i (mergeAtVertex).
// The radius r_i = vcmRadius(r_1, i, alpha) with r_1 a fraction of the scene's bounding radius.
// Without merging (vcm-bpt) there is no light pass: each pixel traces its light subpath right
// after its camera subpath, from the same random numbers, as lesson 7's bptSample does, and the
// image is bpt's. With merging the light subpaths must all exist before the first camera
// subpath, so they come from random numbers of their own (README, section 1.9).
#include <omp.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include "13-vcm/vcm.h"
#include "tasks.h"

namespace ps {

Color vcmSample(const Scene& scene, const Vec2& raster, Rng& rng, const VcmOptions& opt, const MergeOptions& merge,
                const LightVertices* lights, uint32_t pixel, const SplatTarget& splat,
                const VcmSampleRecorders& recorders) {
    thread_local Subpath camera, light;
    thread_local MergeSums cameraSums, lightSums;
    const int maxDepth = scene.settings.maxDepth;
    cameraSubpath(scene, rng, raster, maxDepth, opt.heuristic, camera);
    mergeSums(camera, opt.heuristic, cameraSums);
    Color L(0.0f);
    const bool merging = lights != nullptr && opt.mode != VcmMode::Bpt && merge.radius > 0.0 && merge.lightPaths > 0;
    if (opt.mode == VcmMode::Vcm || opt.mode == VcmMode::Bpt) {
        if (lights == nullptr) {  // no light pass: lesson 7's order of random numbers
            lightSubpath(scene, rng, maxDepth, opt.heuristic, light);
            mergeSums(light, opt.heuristic, lightSums);
        } else {  // the pixel's light subpath of the light pass
            const PathVertex* y = lights->subpath(pixel);
            const double* d = lights->subpathSums(pixel);
            light.assign(y, y + lights->length(pixel));
            lightSums.assign(d, d + lights->length(pixel));
        }
        VcmMis mis;
        mis.heuristic = opt.heuristic;
        mis.eta = merging ? mergeFactor(merge.radius, merge.lightPaths) : 0.0;
        BptOptions bpt;
        bpt.heuristic = opt.heuristic;
        bpt.techniqueWeight = [&](float w, const PathVertex* y, int s, const PathVertex* z, int t,
                                  const ReversePdfs& rev) {
            const double m = mergeTerms({y, lightSums.data(), s}, {z, cameraSums.data(), t}, rev, opt.heuristic);
            return misWeightConnection(w, m, mis);
        };
        L += connectSubpaths(scene, camera, light, raster, rng, bpt, splat, recorders.connections);
    } else {
        // Photon mapping: a camera subpath that reaches a light through specular vertices alone
        // (L S* E) is the one path no merge can make; it counts in full.
        for (size_t t = 2; t <= camera.size(); ++t) {
            const Connection c = connectEmitter(scene, camera.data(), int(t));
            if (c.valid) {
                L += c.value;
                if (recorders.connections) recorders.connections->add(0, int(t), raster, c.value, c.value);
            }
            if (!camera[t - 1].specular) break;
        }
    }
    if (merging) {
        for (int f = 1; f < int(camera.size()); ++f) {
            if (!mergeable(camera.data(), f)) continue;
            L += mergeAtVertex(scene, camera, cameraSums, f, *lights, merge, recorders.merges);
            if (opt.mode == VcmMode::Ppm) break;  // the first non-specular vertex only
        }
    }
    return L;
}

namespace {

double seconds(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

struct VcmIntegrator : Integrator {
    VcmOptions opt;
    LightVertices lights;  // kept from iteration to iteration: the vectors keep their capacity
    // What the report prints: per iteration, the light vertices a merge may use, the memory of
    // the light pass, and the wall times of its parts.
    size_t iterations = 0, storedVertices = 0, pathVertices = 0, bytes = 0, maxBytes = 0, searches = 0, found = 0;
    double lightSeconds = 0.0, treeSeconds = 0.0, cameraSeconds = 0.0;

    explicit VcmIntegrator(const VcmOptions& o) : opt(o) { techniques = vcmTechniqueRenderer(opt); }

    std::vector<std::string> leftOut(const Scene& scene) const override {
        if (opt.mode != VcmMode::Vcm && opt.mode != VcmMode::Bpt) return {};
        BptOptions bpt;
        bpt.heuristic = opt.heuristic;
        return bptLeftOut(scene, bpt);
    }

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        using clock = std::chrono::steady_clock;
        const MergeOptions m = vcmMergeOptions(opt, scene, iteration, out.width * out.height);
        const bool lightPass = opt.mode != VcmMode::Bpt;
        const auto t0 = clock::now();
        auto t1 = t0, t2 = t0;
        if (lightPass) {
            traceLightSubpaths(scene, m.lightPaths, opt.heuristic, seed, iteration, lights, stats);
            t1 = clock::now();
            buildLightVertexTree(lights);
            t2 = clock::now();
        }
        renderPixelTasks(seed, iteration, out, stats, true, [&](int pixel, Rng& rng, Task& task) {
            const Vec2 raster = jitteredRaster(pixel, out.width, rng);
            return vcmSample(scene, raster, rng, opt, m, lightPass ? &lights : nullptr, uint32_t(pixel), task.splat,
                             {});
        });
        const auto t3 = clock::now();
        ++iterations;
        lightSeconds += seconds(t0, t1);
        treeSeconds += seconds(t1, t2);
        cameraSeconds += seconds(t2, t3);
        if (lightPass) {
            const size_t b = lights.vertices.capacity() * sizeof(PathVertex) + lights.sums.capacity() * sizeof(double) +
                             lights.starts.capacity() * sizeof(uint32_t) +
                             lights.refs.capacity() * sizeof(LightVertexRef) + lights.tree.p.capacity() * sizeof(Vec3) +
                             lights.tree.item.capacity() * sizeof(uint32_t) + lights.tree.axis.capacity();
            storedVertices += lights.refs.size();
            searches += lights.searches;
            found += lights.found;
            pathVertices += lights.vertices.size();
            bytes += b;
            maxBytes = std::max(maxBytes, b);
        }
    }

    std::vector<std::string> report() const override {
        if (iterations == 0 || opt.mode == VcmMode::Bpt) return {};
        const double n = double(iterations);
        char line[256];
        std::vector<std::string> out;
        std::snprintf(line, sizeof line,
                      "light pass: %.0f light vertices per iteration, %.0f of them stored in the kd-tree for merging; "
                      "memory %.1f MB per iteration (at most %.1f MB)",
                      double(pathVertices) / n, double(storedVertices) / n, double(bytes) / n / 1e6,
                      double(maxBytes) / 1e6);
        out.push_back(line);
        std::snprintf(line, sizeof line,
                      "merging: %.0f searches per iteration, %.2f light vertices found within r per search",
                      double(searches) / n, searches ? double(found) / double(searches) : 0.0);
        out.push_back(line);
        std::snprintf(line, sizeof line,
                      "wall time per iteration: light subpaths %.1f ms, kd-tree build %.1f ms, camera pass "
                      "(connections and merges) %.1f ms",
                      1e3 * lightSeconds / n, 1e3 * treeSeconds / n, 1e3 * cameraSeconds / n);
        out.push_back(line);
        return out;
    }
};

template <VcmMode mode, Heuristic heuristic = Heuristic::Power>
struct Registered : VcmIntegrator {
    static VcmOptions options() {
        VcmOptions o;
        o.mode = mode;
        o.heuristic = heuristic;
        return o;
    }
    Registered() : VcmIntegrator(options()) {}
};
using Vcm = Registered<VcmMode::Vcm>;
using VcmBalance = Registered<VcmMode::Vcm, Heuristic::Balance>;
using VcmBpt = Registered<VcmMode::Bpt>;
using VcmBpm = Registered<VcmMode::Bpm>;
using VcmPpm = Registered<VcmMode::Ppm>;

}  // namespace

double vcmFirstRadius(const VcmOptions& opt, const Scene& scene, int lightPaths) {
    return opt.radiusFactor * double(scene.radius) * 512.0 / std::sqrt(double(std::max(lightPaths, 1)));
}

MergeOptions vcmMergeOptions(const VcmOptions& opt, const Scene& scene, uint32_t iteration, int lightPaths) {
    MergeOptions m;
    m.mode = opt.mode;
    m.heuristic = opt.heuristic;
    m.lightPaths = lightPaths;
    m.maxDepth = scene.settings.maxDepth;
    if (opt.mode != VcmMode::Bpt)
        m.radius = vcmRadius(vcmFirstRadius(opt, scene, m.lightPaths), int(iteration) + 1, opt.alpha);
    return m;
}

std::unique_ptr<Integrator> makeVcmIntegrator(const VcmOptions& opt) { return std::make_unique<VcmIntegrator>(opt); }

// Each renders its techniques alone too (`pathspace pyramid --algo vcm`: merging cells beside
// the connections, vcm_pyramid.cpp).
PS_REGISTER_INTEGRATOR_CAPS(Vcm, "vcm",
                            "vertex connection and merging: bpt's connections and merges at every camera vertex, "
                            "power-heuristic MIS over both, shrinking radius (lesson 13)",
                            IntegratorCaps().withTechniqueImages());
PS_REGISTER_INTEGRATOR_CAPS(VcmBalance, "vcm-balance", "vcm with the balance heuristic (lesson 13)",
                            IntegratorCaps().withTechniqueImages());
PS_REGISTER_INTEGRATOR_CAPS(VcmBpt, "vcm-bpt", "vcm without merging: lesson 7's bpt, bit for bit (lesson 13)",
                            IntegratorCaps().withTechniqueImages());
PS_REGISTER_INTEGRATOR_CAPS(VcmBpm, "vcm-bpm",
                            "bidirectional photon mapping: merges at every camera vertex weighted by MIS, no "
                            "connections (lesson 13)",
                            IntegratorCaps().withTechniqueImages());
PS_REGISTER_INTEGRATOR_CAPS(VcmPpm, "vcm-ppm",
                            "progressive photon mapping as vcm's special case: one merge at the first non-specular "
                            "camera vertex (lesson 13)",
                            IntegratorCaps().withTechniqueImages());

}  // namespace ps
