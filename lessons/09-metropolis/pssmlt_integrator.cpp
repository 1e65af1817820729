// Lesson 9 — the integrator "pssmlt" (plumbing: read it, nothing to write here): Metropolis light
// transport in primary sample space over lesson 3's path tracer (LiMIS), with the pieces of
// primary_samples.cpp, bootstrap.cpp and mlt_step.cpp (Eq. 9.7-9.11).
//
//   iteration 0   the bootstrap: bootstrapPerPixel x pixels seed paths, each from its own generator
//                 (one task item each); b and the chains' starts (bootstrapChains); each chain
//                 replays its seed path's numbers to take it as its first state.
//   every         as many Metropolis steps as the image has pixels (one "sample per pixel"), shared
//   iteration     by the chains: chain c is item c of framework/tasks.h's loop, its steps draw from
//                 taskRng(seed, iteration, c), its splats go to its task's list with the factor
//                 b pixels / steps: the image is bit-identical for any number of threads.
#include <algorithm>
#include "03-path-tracing/pathtracer.h"
#include "09-metropolis/pssmlt.h"
#include "tasks.h"

namespace ps {

namespace {
// Seeds of the bootstrap and of the chains' primary samples, apart from the steps' own.
constexpr uint64_t kBootstrapTag = 0x6d6c742d626f6f74ull;  // "mlt-boot"
constexpr uint64_t kSamplesTag = 0x6d6c742d7072696dull;    // "mlt-prim"
}  // namespace

PathSample PSSMLT::evaluatePath(const Scene& scene, Rng& replay, SampleStats& stats) {
    PathSample s;
    const float u0 = replay.uniform();
    const float u1 = replay.uniform();
    s.raster = Vec2(u0 * float(scene.camera.width()), u1 * float(scene.camera.height()));
    const Color L = LiMIS(scene, scene.camera.generateRay(s.raster), replay, scene.settings.maxDepth);
    if (!isFinite(L)) {
        checkSample(L, stats);  // counted as NaN or Inf; the path carries nothing
        return s;
    }
    s.L = L;
    s.I = std::max(0.0f, luminance(L));
    return s;
}

void PSSMLT::start(const Scene& scene, uint64_t seed, int pixels, SampleStats& stats) {
    const uint64_t bootSeed = mix64(seed ^ kBootstrapTag);
    const int n = std::max(1, settings_.bootstrapPerPixel) * pixels;
    std::vector<float> I(size_t(n), 0.0f);
    runTasks(TaskLoop(n, bootSeed, 0), stats,
             [&](int i, Rng& rng, Task& task) { I[size_t(i)] = evaluatePath(scene, rng, task.stats).I; });
    const int chains = settings_.chains > 0 ? settings_.chains : std::max(1, pixels / 64);
    Rng pick = taskRng(bootSeed, 1, 0);
    const Bootstrap boot = bootstrapChains(I, chains, pick);
    b_ = boot.b;
    chains_.clear();
    stepsPerChain_ = 0;
    if (boot.starts.size() != size_t(chains) || !(b_ > 0.0)) return;  // nothing to see (or the TODO)
    chains_.resize(size_t(chains));
    stepsPerChain_ = (pixels + chains - 1) / chains;
    // Chain c's first state: its seed path, replayed from the same generator (a large step reads
    // every coordinate afresh, in order, from it).
    runTasks(TaskLoop(chains, bootSeed, 2), stats, [&](int c, Rng&, Task& task) {
        Chain& chain = chains_[size_t(c)];
        chain.samples = PrimarySamples(taskRng(bootSeed, 0, boot.starts[size_t(c)]));
        chain.samples.startProposal(true);
        Rng replay;
        replay.replayFrom(&chain.samples);
        chain.current = evaluatePath(scene, replay, task.stats);
        chain.samples.accept();
    });
}

void PSSMLT::renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out, SampleStats& stats) {
    const int pixels = out.width * out.height;
    if (iteration == 0) start(scene, seed, pixels, stats);
    if (chains_.empty()) return;
    const int chains = int(chains_.size());
    SplatBuffer splats(out.width, out.height, size_t(taskCount(chains)));
    // Eq. 9.11: pixel j = b pixels / M times the weighted sum of L / I of the splats in it.
    const float scale = float(b_ * double(pixels) / double(stepsPerIteration()));
    const uint64_t samplesSeed = mix64(seed ^ kSamplesTag);
    TaskLoop loop(chains, seed, iteration);
    loop.splats = &splats;
    loop.splatScale = scale;
    runTasks(loop, stats, [&](int c, Rng& rng, Task& task) {
        Chain& chain = chains_[size_t(c)];
        chain.samples.setRng(taskRng(samplesSeed, iteration, uint32_t(c)));
        const PathEvaluator evaluate = [&](Rng& replay) { return evaluatePath(scene, replay, task.stats); };
        const SplatFunction splat = [&](const Vec2& raster, const Color& col) { task.splat.add(raster, col); };
        for (int k = 0; k < stepsPerChain_; ++k) mltStep(chain, settings_.pLarge, rng, evaluate, splat);
    });
    splats.resolve(out);
}

PS_REGISTER_INTEGRATOR(PSSMLT, "pssmlt",
                       "Metropolis light transport in primary sample space over the path tracer pt (lesson 9)");

}  // namespace ps
