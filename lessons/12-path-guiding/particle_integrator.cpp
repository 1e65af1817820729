// Lesson 12 — roulette and splitting for particles (plumbing: read it, nothing to write here): the
// camera pass that leaves importons and estimates the image's total (Eq. 12.16, 12.17), the
// importance cache it fills (lesson 10's AdjointCache, each entry the mean of lesson 8's density
// estimates at its importons), and the integrators "lt-adrrs" (lesson 5's light tracer) and
// "ppm-adrrs" (lesson 8's progressive photon mapping) whose light walks take particleDecision as
// their continuation rule.
//
//   iteration 0   the camera pass: ImportancePass::paths camera paths of lesson 3's pt (path i
//                 through pixel i mod pixels, each from its own generator), their importons
//                 (appendImportons) in task order, lesson 8's kd-tree over them, and at most
//                 kMaxQueries of them (every stride-th) asked for the importance reflected there
//                 (radianceEstimate with a white Lambertian material), in parallel, each result in
//                 its own slot, added to the cache in importon order: the same cache for any
//                 number of threads.
//   every         the light paths, as lesson 5's (or lesson 8's) integrator traces them, with the
//   iteration     continuation rule.
#include <algorithm>
#include <memory>
#include <sstream>
#include "12-path-guiding/guiding.h"
#include "tasks.h"

namespace ps {

namespace {

constexpr uint64_t kImportanceTag = 0x696d706f72746f6eull;  // "importon"
constexpr int kMaxQueries = 1 << 15;                        // density estimates for the cache
constexpr int kImportonsPerEstimate = 32;                   // k of lesson 8's k-nearest estimate

}  // namespace

ImportancePass importancePass(const Scene& scene, int paths, uint64_t seed, SampleStats& stats) {
    ImportancePass pass;
    pass.paths = paths;
    pass.cache = AdjointCache(scene.bounds, kCacheResolution);
    const int width = scene.camera.width(), pixels = width * scene.camera.height();
    const int maxDepth = scene.settings.maxDepth;
    std::vector<std::vector<Photon>> lists(size_t(taskCount(paths)));
    std::vector<std::vector<ImportanceVertex>> where(lists.size());
    std::vector<double> sums(lists.size(), 0.0);
    runTasks(TaskLoop(paths, seed, 0), stats, [&](int i, Rng& rng, Task& task) {
        const Vec2 raster = jitteredRaster(i % pixels, width, rng);
        std::vector<ImportanceVertex> path;
        Color L(0.0f);
        const Ray ray = cameraRay(scene.camera, raster, rng);
        cameraWalk(scene, ray, rng, {maxDepth}, [&](const WalkVertex& v) {
            ImportanceVertex x;
            x.store = v.hit && !scene.materials[v.sp.material].isDelta();
            if (v.hit) x.p = v.sp.p, x.n = v.sp.n;
            x.wo = v.wo;
            x.beta = v.beta;
            path.push_back(x);
            addMISContribution(scene, v, rng, maxDepth, L);
            return true;
        });
        appendImportons(path, pixels, paths, lists[task.index]);
        for (const ImportanceVertex& x : path)
            if (x.store) where[task.index].push_back(x);
        const Color l = checkSample(L, task.stats);
        sums[task.index] += (double(l.r) + l.g + l.b) / 3.0;
    });
    std::vector<Photon> importons;
    std::vector<ImportanceVertex> at;
    double total = 0.0;
    for (size_t t = 0; t < lists.size(); ++t) {  // in task order
        importons.insert(importons.end(), lists[t].begin(), lists[t].end());
        at.insert(at.end(), where[t].begin(), where[t].end());
        total += sums[t];
    }
    pass.imageTotal = float(total * double(pixels) / double(paths));
    pass.importons = importons.size();
    if (importons.empty() || importons.size() != at.size()) return pass;
    PhotonMap map;
    buildPhotonMap(importons, map);
    // The importance reflected by a white Lambertian surface at every stride-th importon.
    Material white;
    white.kind = BSDFKind::Diffuse;
    white.albedo = Color(1.0f);
    EstimateOptions opt;
    opt.k = kImportonsPerEstimate;
    opt.maxRadius = 0.1f * scene.radius;
    const size_t stride = std::max<size_t>(1, (at.size() + kMaxQueries - 1) / kMaxQueries);
    const int queries = int((at.size() + stride - 1) / stride);
    std::vector<Color> estimate(static_cast<size_t>(queries), Color(0.0f));
    runTasks(TaskLoop(queries, seed, 1), stats, [&](int q, Rng&, Task&) {
        const ImportanceVertex& x = at[size_t(q) * stride];
        SurfacePoint sp;
        sp.p = x.p;
        sp.n = x.n;
        estimate[size_t(q)] = radianceEstimate(map, sp, white, x.wo, opt);
    });
    for (int q = 0; q < queries; ++q) {
        const ImportanceVertex& x = at[size_t(q) * stride];
        if (isFinite(estimate[size_t(q)])) pass.cache.add(pass.cache.entry(x.p, x.n, x.wo), estimate[size_t(q)]);
    }
    return pass;
}

ContinuationRule particleRule(const Scene& scene, const ImportancePass& pass, ParticleCounts& counts) {
    auto paths = std::make_shared<int>(1);
    return [&scene, &pass, &counts, paths](const WalkVertex& v, Rng& r) {
        const Decision d = particleDecision(pass.cache, scene, v, pass.imageTotal);
        if (!d.decided) return Continuations{1, v.beta};  // the walk's own roulette after the bounce
        const float q = *paths >= kMaxPathsPerCameraRay ? std::min(d.q, 1.0f) : d.q;
        counts.decisions.fetch_add(1, std::memory_order_relaxed);
        if (q < 1.0f) counts.roulette.fetch_add(1, std::memory_order_relaxed);
        if (q > 1.0f) counts.splits.fetch_add(1, std::memory_order_relaxed);
        Continuations c = continuations(v.beta, q, r);
        c.roulette = false;  // the rule decided survival here
        if (c.n > 0) *paths += c.n - 1;
        return c;
    };
}

namespace {

std::string describe(const ImportancePass& pass, const ParticleCounts& counts) {
    const uint64_t decisions = counts.decisions, roulette = counts.roulette, splits = counts.splits;
    std::ostringstream s;
    s.precision(3);
    s << "importance: " << pass.cache.reliableEntries() << " of " << pass.cache.entries() << " entries reliable from "
      << pass.importons << " importons of " << pass.paths << " camera paths; " << decisions
      << " decisions: " << (decisions ? 100.0 * double(roulette) / double(decisions) : 0.0) << " % roulette, "
      << (decisions ? 100.0 * double(splits) / double(decisions) : 0.0) << " % splitting";
    return s.str();
}

int cameraPassPaths(const Image& out) { return std::max(1 << 14, 4 * out.width * out.height); }

// What lt-adrrs and ppm-adrrs share: the camera pass's importons, made at a render's first
// iteration and used by all its passes, and the counts of the particles' decisions.
struct ParticleIntegrator : Integrator {
    ImportancePass pass;
    ParticleCounts counts;
    void startRender(const Scene& scene, uint32_t iteration, uint64_t seed, const Image& out, SampleStats& stats) {
        if (iteration != 0) return;
        pass = importancePass(scene, cameraPassPaths(out), mix64(seed ^ kImportanceTag), stats);
        counts.reset();
    }
    std::vector<std::string> report() const override { return {describe(pass, counts)}; }
};

struct ADRRSLightTracer : ParticleIntegrator {
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        startRender(scene, iteration, seed, out, stats);
        renderLightPathTasks(seed, iteration, out, stats, [&](int, Rng& rng, Task& task) {
            WalkOptions opt(scene.settings.maxDepth);
            opt.continuation = particleRule(scene, pass, counts);
            traceLightPath(scene, rng, opt, task.splat);
        });
    }
};

// Progressive photon mapping (lesson 8's ppm) whose photons are rouletted and split by the same
// rule, one rule (and count of paths) per photon path.
struct ADRRSPhotonMapper : ParticleIntegrator {
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        startRender(scene, iteration, seed, out, stats);
        renderPpmPass(scene, iteration, seed, out, stats, [&] { return particleRule(scene, pass, counts); });
    }
};

}  // namespace

PS_REGISTER_INTEGRATOR_CAPS(
    ADRRSLightTracer, "lt-adrrs",
    "light tracing with roulette and splitting by visual importance from a camera pass (lesson 12)",
    IntegratorCaps().withCameraModels());
PS_REGISTER_INTEGRATOR_CAPS(ADRRSPhotonMapper, "ppm-adrrs",
                            "progressive photon mapping, photons rouletted and split by visual importance (lesson 12)",
                            IntegratorCaps().withCameraModels());

}  // namespace ps
