// Lesson 10 — the integrator "pt-adrrs" (plumbing: read it, nothing to write here): lesson 3's path
// tracer (its visitor addMISContribution, Eq. 3.7) on the walk with survival and splitting
// (splitting_walk.cpp, Algorithm 10.1), which asks adrrsContinuations (decision.cpp) at every vertex.
//
//   iteration 0   the pre-pass (Eq. 10.8): prePassPerPixel paths per pixel of lesson 3's pt (at
//                 least prePassMinimum), each
//                 from its own generator (one task item each); each path's continuationSamples go
//                 to its task's list, and the lists are added to the cache in task order, so the
//                 cache is the same for any number of threads.
//   every         one camera ray per pixel: its pixel estimate I~ at the first vertex (Eq. 10.9),
//   iteration     then the tree of paths, depth first, all from the pixel's own generator
//                 (taskRng(seed, iteration, pixel)): the image is bit-identical for any number of
//                 threads.
//
// It counts, per camera ray, the vertices of its tree and those on branches that add nothing to
// the image (PathCounts; the render command prints them after its summary).
#include <algorithm>
#include <sstream>
#include "10-adrrs/adrrs.h"
#include "tasks.h"

namespace ps {

namespace {
constexpr uint64_t kPrePassTag = 0x616472722d707265ull;  // "adrr-pre"

std::string percent(uint64_t part, uint64_t whole) {
    std::ostringstream s;
    s.precision(3);
    s << (whole > 0 ? 100.0 * double(part) / double(whole) : 0.0) << " %";
    return s.str();
}
}  // namespace

PathCounts& PathCounts::operator+=(const PathCounts& o) {
    cameraRays += o.cameraRays;
    vertices += o.vertices;
    wasted += o.wasted;
    decisions += o.decisions;
    roulette += o.roulette;
    splits += o.splits;
    return *this;
}

AdjointCache ADRRSPathTracer::prePass(const Scene& scene, int paths, int resolution, uint64_t seed,
                                      SampleStats& stats) {
    AdjointCache cache(scene.bounds, resolution);
    if (paths <= 0) return cache;
    const int width = scene.camera.width(), pixels = width * scene.camera.height();
    const int maxDepth = scene.settings.maxDepth;
    std::vector<std::vector<CacheSample>> lists(size_t(taskCount(paths)));
    runTasks(TaskLoop(paths, seed, 0), stats, [&](int i, Rng& rng, Task& task) {
        const Vec2 raster = jitteredRaster(i % pixels, width, rng);
        std::vector<PrePassVertex> path;
        cameraWalk(scene, cameraRay(scene.camera, raster, rng), rng, {maxDepth}, [&](const WalkVertex& v) {
            PrePassVertex x;
            x.beta = v.beta;
            if (v.hit && !scene.materials[v.sp.material].isDelta()) x.entry = cache.entry(v.sp.p, v.sp.n, v.wo);
            x.added = Color(0.0f);
            addMISContribution(scene, v, rng, maxDepth, x.added);
            path.push_back(x);
            return true;
        });
        continuationSamples(path, lists[task.index]);
        for (CacheSample& s : lists[task.index])  // a NaN or Inf sample is counted, and enters as 0
            if (!isFinite(s.value)) s.value = checkSample(s.value, task.stats);
    });
    for (const std::vector<CacheSample>& list : lists)  // in task order
        for (const CacheSample& s : list)
            if (s.entry >= 0 && s.entry < cache.entries()) cache.add(s.entry, s.value);
    return cache;
}

Color ADRRSPathTracer::Li(const Scene& scene, const Ray& ray, Rng& rng, PathCounts& counts) const {
    const int maxDepth = scene.settings.maxDepth;
    Color L(0.0f);
    float I = -1.0f;
    ++counts.cameraRays;
    // The vertices whose branch is still open, as (bounces, adds something): in depth-first
    // order a vertex's branch ends when a vertex with as few bounces or fewer comes (or the tree
    // ends); a branch that ends without adding anything counts its vertex as wasted.
    struct Open {
        int bounces;
        bool adds;
    };
    std::vector<Open> open;
    const auto closeBranches = [&](int bounces) {
        while (!open.empty() && open.back().bounces >= bounces) {
            const Open o = open.back();
            open.pop_back();
            if (!o.adds) ++counts.wasted;
            else if (!open.empty()) open.back().adds = true;
        }
    };
    const WalkVisitor visit = [&](const WalkVertex& v) {
        closeBranches(v.bounces);
        Color added(0.0f);
        addMISContribution(scene, v, rng, maxDepth, added);
        L += added;
        ++counts.vertices;
        open.push_back({v.bounces, !isBlack(added)});
        if (v.bounces == 0 && settings_.roulette == Roulette::ADRRS) I = pixelEstimate(cache_, scene, v);
        return true;
    };
    if (settings_.roulette == Roulette::Classic) {
        cameraWalk(scene, ray, rng, {maxDepth}, visit);
    } else {
        const ExpectedContinuations rule = [&](const WalkVertex& v) {
            const float q = adrrsContinuations(cache_, scene, v, I);
            if (q == kNoDecision) return q;  // lesson 3's roulette plays: not counted
            ++counts.decisions;
            if (q < 1.0f) ++counts.roulette;
            if (q > 1.0f) ++counts.splits;
            return q;
        };
        splittingWalk(scene, ray, rng, maxDepth, rule, visit);
    }
    closeBranches(0);
    return L;
}

void ADRRSPathTracer::renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                                      SampleStats& stats) {
    if (iteration == 0) {
        counts_ = PathCounts();
        if (!haveCache_ && settings_.roulette == Roulette::ADRRS) {
            const int paths = std::max(settings_.prePassPerPixel * out.width * out.height, settings_.prePassMinimum);
            cache_ = prePass(scene, paths, settings_.resolution, mix64(seed ^ kPrePassTag), stats);
            prePassPaths_ = uint64_t(paths);
            haveCache_ = true;
        }
    }
    std::vector<PathCounts> taskCounts(size_t(taskCount(out.width * out.height)));
    renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task& task) {
        const Vec2 raster = jitteredRaster(pixel, out.width, rng);
        return Li(scene, cameraRay(scene.camera, raster, rng), rng, taskCounts[task.index]);
    });
    for (const PathCounts& c : taskCounts) counts_ += c;  // in task order
}

std::vector<std::string> ADRRSPathTracer::report() const {
    std::vector<std::string> lines;
    const PathCounts& c = counts_;
    if (settings_.roulette == Roulette::ADRRS)
        lines.push_back("cache: " + std::to_string(cache_.reliableEntries()) + " of " +
                        std::to_string(cache_.entries()) + " entries reliable after a pre-pass of " +
                        std::to_string(prePassPaths_) + " paths");
    std::ostringstream s;
    s.precision(3);
    s << c.cameraRays << " camera rays, " << c.vertices << " path vertices ("
      << (c.cameraRays ? double(c.vertices) / double(c.cameraRays) : 0.0) << " per camera ray), " << c.wasted
      << " of them wasted (" << percent(c.wasted, c.vertices) << ": on branches that add nothing to the image)";
    lines.push_back(s.str());
    if (settings_.roulette == Roulette::ADRRS)
        lines.push_back(std::to_string(c.decisions) + " decisions: " + percent(c.roulette, c.decisions) +
                        " roulette (q < 1), " + percent(c.splits, c.decisions) + " splitting (q > 1)");
    return lines;
}

PS_REGISTER_INTEGRATOR_CAPS(ADRRSPathTracer, "pt-adrrs",
                            "path tracing with adjoint-driven Russian roulette and splitting (lesson 10)",
                            IntegratorCaps().withCameraModels());

}  // namespace ps
