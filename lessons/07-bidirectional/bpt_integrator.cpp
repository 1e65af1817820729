// Lesson 7 — the bidirectional path tracer the render command knows as `bpt` (plumbing: read
// it, nothing to write here), its variants `bpt-balance` (balance heuristic) and `bpt-full`
// (weights from the full pdf list, Eq. 7.7, instead of the recursive form, Eq. 7.9), and the
// per-technique images of Veach's pyramid (`pathspace pyramid`).
//
// One iteration: for every pixel a camera subpath through a jittered point of the pixel and a
// light subpath (random numbers from taskRng(seed, iteration, pixel), whichever thread runs
// it), then every technique (s, t) (Eq. 7.2). t >= 2 goes to the pixel, t = 1 is splatted with
// the factor 1 / (width * height) of lesson 5 (Eq. 5.4) into a SplatBuffer whose lists are
// added in a fixed order: the image does not depend on the number of threads (the framework's
// task loop, framework/tasks.h). A later lesson's extra techniques (bpt.h: t = 0 with a camera
// whose points rays can hit) are splatted the same way.
//
// Left out where the scene shows it cannot contribute (Eq. 7.12, exact): see bptLeftOut.
#include <omp.h>
#include "07-bidirectional/bpt.h"
#include "tasks.h"

namespace ps {

namespace {

struct Pruning {
    bool s0 = false;         // no light can be hit (point lights only)
    bool deltaEnds = false;  // connections at specular vertices
};
Pruning pruning(const Scene& scene, const BptOptions& opt) {
    Pruning p;
    if (!opt.prune || !scene.settings.prune) return p;
    p.s0 = !scene.caps.areaLights && !scene.caps.backgroundLight;
    p.deltaEnds = true;
    return p;
}
}  // namespace

std::vector<std::string> bptLeftOut(const Scene& scene, const BptOptions& opt) {
    if (!opt.prune || !scene.settings.prune) return {};
    std::vector<std::string> lines;
    if (scene.camera.isPinhole())
        lines.push_back("t = 0 techniques: the pinhole is a delta position no ray can hit (Eq. 7.12)");
    const Pruning p = pruning(scene, opt);
    if (p.s0) lines.push_back("s = 0 techniques: no light can be hit (point lights only) (Eq. 7.12)");
    if (scene.caps.hasDeltaBSDF())
        lines.push_back(
            "connections at specular (mirror, glass) vertices, and light vertices on them are not "
            "connected to the camera: a delta BSDF is 0 for every given pair of directions (Eq. 7.12)");
    return lines;
}

Color bptSample(const Scene& scene, const Vec2& raster, Rng& rng, const BptOptions& opt, const SplatTarget& splat,
                TechniqueRecorder* recorder) {
    thread_local Subpath camera, light;
    const int maxDepth = scene.settings.maxDepth;
    cameraSubpath(scene, rng, raster, maxDepth, opt.heuristic, camera);
    lightSubpath(scene, rng, maxDepth, opt.heuristic, light);
    const Color L = connectSubpaths(scene, camera, light, raster, rng, opt, splat, recorder);
    for (const auto& extra : Registry<ExtraTechnique>::inOrder()) extra.value(scene, light, rng, opt, splat, recorder);
    return L;
}

Color connectSubpaths(const Scene& scene, const Subpath& camera, const Subpath& light, const Vec2& raster, Rng& rng,
                      const BptOptions& opt, const SplatTarget& splat, TechniqueRecorder* recorder) {
    const int maxDepth = scene.settings.maxDepth;
    const Pruning prune = pruning(scene, opt);
    Color L(0.0f);
    const int nCamera = static_cast<int>(camera.size()), nLight = static_cast<int>(light.size());
    for (int t = 1; t <= nCamera; ++t) {
        for (int s = 0; s <= std::max(nLight, 1); ++s) {
            if (s + t < 2 || s + t - 2 > maxDepth) continue;
            if (t == 1 && s == 0) continue;
            if (s > nLight && !(s == 1 && t >= 2)) continue;  // s = 1 samples its own light vertex
            if (s == 0 && prune.s0) continue;
            if (prune.deltaEnds && t >= 2 && camera[size_t(t - 1)].specular) continue;
            if (prune.deltaEnds && s >= 2 && light[size_t(s - 1)].specular) continue;
            if (prune.deltaEnds && t == 1 && light[size_t(s - 1)].specular) continue;
            float uLight = 0.0f;
            Vec2 uPos(0.0f);
            if (s == 1 && t >= 2) {
                uLight = rng.uniform();
                uPos = rng.uniform2();
            }
            if (opt.techniqueFilter && !opt.techniqueFilter(light, camera, s, t)) continue;
            const Connection c = connect(scene, light, camera, s, t, uLight, uPos);
            if (!c.valid) continue;
            const PathVertex* y = s == 1 ? &c.sampledLight : light.data();
            float w = opt.recursive ? misWeightRecursive(y, s, camera.data(), t, c.rev, opt.heuristic)
                                    : misWeightFull(y, s, camera.data(), t, c.rev, opt.heuristic);
            if (opt.techniqueWeight) w = opt.techniqueWeight(w, y, s, camera.data(), t, c.rev);
            const Color weighted = c.value * w;
            if (t == 1) {
                splat.add(c.raster, weighted);
                if (recorder) recorder->add(s, t, c.raster, c.value * splat.scale, weighted * splat.scale);
            } else {
                L += weighted;
                if (recorder) recorder->add(s, t, raster, c.value, weighted);
            }
        }
    }
    return L;
}

namespace {

struct BptBase : Integrator {
    BptBase() {
        techniques = bptTechniqueRenderer([this](const Scene&) { return opt; });
    }
    BptOptions opt;
    std::vector<std::string> leftOut(const Scene& scene) const override { return bptLeftOut(scene, opt); }

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        renderPixelTasks(seed, iteration, out, stats, true, [&](int pixel, Rng& rng, Task& task) {
            const Vec2 raster = jitteredRaster(pixel, out.width, rng);
            return bptSample(scene, raster, rng, opt, task.splat, nullptr);
        });
    }
};

struct BptPower : BptBase {};
struct BptBalance : BptBase {
    BptBalance() { opt.heuristic = Heuristic::Balance; }
};
struct BptFull : BptBase {
    BptFull() { opt.recursive = false; }
};

// Accumulation of the technique images for one task (a fixed block of pixels) of one iteration.
// t >= 2 lands in the task's own pixels and is added at once (no other task writes there);
// t = 1 (and t = 0) lands anywhere and is kept in the task's list, added after the iteration in task order,
// so the images do not depend on the number of threads. NaN/Inf values are counted and left out.
struct ImageRecorder : TechniqueRecorder {
    struct Splat {
        size_t technique;
        int x, y;
        Color unweighted, weighted;
    };
    TechniqueImages* images = nullptr;
    std::vector<Splat>* splats = nullptr;  // this task's t = 1 list
    SampleStats* stats = nullptr;
    void add(int s, int t, const Vec2& raster, const Color& unweighted, const Color& weighted) override {
        const int k = s + t - 1;
        if (k < 1 || k > images->maxLength) return;
        const size_t i = size_t(techniqueIndex(s, k));
        const int x = std::clamp(static_cast<int>(raster.x), 0, images->unweighted[i].width - 1);
        const int y = std::clamp(static_cast<int>(raster.y), 0, images->unweighted[i].height - 1);
        if (!isFinite(unweighted) || !isFinite(weighted)) {
            checkSample(isFinite(unweighted) ? weighted : unweighted, *stats);
            return;
        }
        if (t <= 1) splats->push_back({i, x, y, unweighted, weighted});
        else accumulate(*images, i, x, y, unweighted, weighted);
    }
    static void accumulate(TechniqueImages& images, size_t i, int x, int y, const Color& u, const Color& w) {
        images.unweighted[i].at(x, y) += u;
        images.weighted[i].at(x, y) += w;
        images.unweightedSq[i].at(x, y) += u * u;
    }
};

TechniqueImages emptyTechniques(int maxLength, int w, int h) {
    TechniqueImages t;
    t.maxLength = maxLength;
    const size_t n = size_t(techniqueCount(maxLength));
    t.unweighted.assign(n, Image(w, h));
    t.weighted.assign(n, Image(w, h));
    t.unweightedSq.assign(n, Image(w, h));
    return t;
}

}  // namespace

TechniqueImages renderTechniques(const Scene& scene, int maxLength, int spp, uint64_t seed, int threads,
                                 const BptOptions& opt) {
    const int w = scene.camera.width(), h = scene.camera.height(), pixels = w * h;
    if (threads > 0) omp_set_num_threads(threads);
    Scene limited = scene;
    limited.settings.maxDepth = std::min(scene.settings.maxDepth, maxLength - 1);
    TechniqueImages out = emptyTechniques(maxLength, w, h);
    std::vector<std::vector<ImageRecorder::Splat>> lists(static_cast<size_t>(taskCount(pixels)));
    for (int it = 0; it < spp; ++it) {
        // No SplatBuffer: bptSample's own t = 1 splats (the weighted image) are not wanted here.
        TaskLoop loop(pixels, seed, uint32_t(it));
        loop.splatScale = 1.0f / static_cast<float>(pixels);
        runTasks(loop, out.stats, [&](int pixel, Rng& rng, Task& task) {
            ImageRecorder recorder;
            recorder.images = &out;
            recorder.splats = &lists[task.index];
            recorder.stats = &task.stats;
            const Vec2 raster = jitteredRaster(pixel, w, rng);
            bptSample(limited, raster, rng, opt, task.splat, &recorder);
        });
        for (auto& list : lists) {  // t = 1, in task order
            for (const ImageRecorder::Splat& sp : list)
                ImageRecorder::accumulate(out, sp.technique, sp.x, sp.y, sp.unweighted, sp.weighted);
            list.clear();
        }
    }
    out.spp = spp;
    const float inv = 1.0f / static_cast<float>(spp);
    for (size_t i = 0; i < out.unweighted.size(); ++i)
        for (size_t q = 0; q < out.unweighted[i].pixels.size(); ++q) {
            out.unweighted[i].pixels[q] *= inv;
            out.weighted[i].pixels[q] *= inv;
            out.unweightedSq[i].pixels[q] *=
                inv * inv;  // sum of squares / spp^2: the variance of the mean (an upper bound)
        }
    return out;
}

TechniqueRenderer bptTechniqueRenderer(std::function<BptOptions(const Scene&)> options) {
    TechniqueRenderer r;
    r.layout = [](int maxLength) {
        std::vector<TechniqueRow> rows;
        for (int k = 1; k <= maxLength; ++k) {
            TechniqueRow row;
            row.label = "k=" + std::to_string(k);
            for (int s = 0; s <= k + 1; ++s) {
                const std::string st = std::to_string(s) + "," + std::to_string(k + 1 - s);
                row.cells.push_back({std::to_string(s) + "-" + std::to_string(k + 1 - s), "(" + st + ")", {}, {}});
            }
            rows.push_back(row);
        }
        return rows;
    };
    r.render = [layout = r.layout, options](const Scene& scene, const TechniqueImagesOptions& o) {
        const TechniqueImages t = renderTechniques(scene, o.maxLength, o.spp, o.seed, o.threads, options(scene));
        TechniquePyramid p;
        p.rows = layout(o.maxLength);
        p.stats = t.stats;
        for (int k = 1; k <= o.maxLength; ++k)
            for (int s = 0; s <= k + 1; ++s) {
                TechniqueCell& cell = p.rows[size_t(k - 1)].cells[size_t(s)];
                cell.unweighted = t.unweighted[size_t(techniqueIndex(s, k))];
                cell.weighted = t.weighted[size_t(techniqueIndex(s, k))];
            }
        return p;
    };
    return r;
}

// Every technique renders a camera model's paths too (its points are the camera subpath's first
// vertex; a later lesson's extra technique adds t = 0 where rays can hit them).
PS_REGISTER_INTEGRATOR_CAPS(
    BptPower, "bpt",
    "bidirectional path tracing: all (s, t) connections, power-heuristic MIS (recursive form) (lesson 7)",
    IntegratorCaps().withCameraModels().withTechniqueImages());
PS_REGISTER_INTEGRATOR_CAPS(BptBalance, "bpt-balance", "bpt with the balance heuristic (lesson 7)",
                            IntegratorCaps().withCameraModels().withTechniqueImages());
PS_REGISTER_INTEGRATOR_CAPS(BptFull, "bpt-full", "bpt with MIS weights from the full pdf list (lesson 7)",
                            IntegratorCaps().withCameraModels().withTechniqueImages());

}  // namespace ps
