// Lesson 9 — the integrator "mmlt" (plumbing: read it, nothing to write here): multiplexed
// Metropolis light transport over lesson 7's BPT (Hachisuka et al. 2014), with the pieces of
// mmlt_target.cpp, technique_mutation.cpp and mmlt_step.cpp (Eq. 9.12-9.16), and what they need:
// the subpaths of a point of primary sample space and the connection of one technique.
//
//   iteration 0   the bootstrap, per path length k = 1 .. maxDepth + 1 (lesson 7's s + t - 2 <=
//                 maxDepth): bootstrapPerPixel x pixels / (maxDepth + 1) seed samples each, a
//                 seed sample being fresh camera and light streams (each from its own generator,
//                 one task item each) whose subpaths are evaluated with EVERY technique s = 0 .. k:
//                 the k + 1 pairs (u, s) of a seed enter lesson 9's bootstrapChains together, which
//                 gives b_k (their mean: the expectation over s ~ p_k taken exactly, Eq. 9.15) and
//                 the pairs length k's chains start from. The chains are shared out among the
//                 lengths: one for every length with b_k > 0, the rest in proportion to b_k (largest
//                 remainders). Each chain replays its seed sample's streams and takes its s.
//   every         as many steps as the image has pixels (one "sample per pixel"), the same number
//   iteration     for every chain: chain c is item c of framework/tasks.h's loop, its steps draw
//                 from taskRng(seed, iteration, c), its streams from generators of (iteration, c),
//                 its splats go to its task's list times b_k pixels / M_k, M_k the steps of all
//                 chains of its length (Eq. 9.16): bit-identical for any number of threads.
#include <algorithm>
#include <cmath>
#include <numeric>
#include "09-metropolis/mmlt.h"
#include "tasks.h"

namespace ps {

namespace {
// Seeds of the bootstrap's streams and techniques and of the chains' streams, apart from the steps'.
constexpr uint64_t kBootCameraTag = 0x6d6d6c742d625f63ull;  // "mmlt-b_c"
constexpr uint64_t kBootLightTag = 0x6d6d6c742d625f6cull;   // "mmlt-b_l"
constexpr uint64_t kPickTag = 0x6d6d6c742d706b21ull;        // "mmlt-pk!"
constexpr uint64_t kCameraTag = 0x6d6d6c742d63616dull;      // "mmlt-cam"
constexpr uint64_t kLightTag = 0x6d6d6c742d6c6974ull;       // "mmlt-lit"

// The target with NaN/Inf counted: such a sample carries nothing.
PathSample evaluateTarget(const Scene& scene, const SubpathPair& paths, int k, int s, SampleStats& stats) {
    PathSample y = multiplexedTarget(scene, paths, k, s);
    if (!isFinite(y.L) || !std::isfinite(y.I)) {
        checkSample(y.L, stats);
        y.L = Color(0.0f);
        y.I = 0.0f;
    }
    return y;
}

// Connections a scene cannot use (Eq. 7.12, as lesson 7's bpt prunes them): exact, 0 anyway.
bool pruned(const Scene& scene, const SubpathPair& p, int s, int t) {
    if (!scene.settings.prune) return false;
    if (s == 0 && !scene.caps.areaLights && !scene.caps.backgroundLight) return true;
    if (t >= 2 && p.camera[size_t(t - 1)].specular) return true;
    if (s >= 2 && p.light[size_t(s - 1)].specular) return true;
    return t == 1 && p.light[size_t(s - 1)].specular;
}
}  // namespace

void traceSubpaths(const Scene& scene, int k, Rng& cameraStream, Rng& lightStream, SubpathPair& out) {
    const float u0 = cameraStream.uniform();
    const float u1 = cameraStream.uniform();
    out.raster = Vec2(u0 * float(scene.camera.width()), u1 * float(scene.camera.height()));
    cameraSubpath(scene, cameraStream, out.raster, k - 1, Heuristic::Power, out.camera);
    out.uLight = lightStream.uniform();
    const float a = lightStream.uniform();
    const float b = lightStream.uniform();
    out.uPos = Vec2(a, b);
    lightSubpath(scene, lightStream, k - 1, Heuristic::Power, out.light);
}

Connection connectTechnique(const Scene& scene, const SubpathPair& paths, int s, int t) {
    const int nCamera = int(paths.camera.size()), nLight = int(paths.light.size());
    if (s < 0 || t < 1 || s + t < 2 || t > nCamera) return Connection{};
    if (s > nLight && !(s == 1 && t >= 2)) return Connection{};  // s = 1 samples its own light vertex
    if (pruned(scene, paths, s, t)) return Connection{};
    return connect(scene, paths.light, paths.camera, s, t, paths.uLight, paths.uPos);
}

double MMLT::b() const {
    double sum = 0.0;
    for (const PathLength& l : lengths_) sum += l.b;
    return sum;
}

void MMLT::start(const Scene& scene, uint64_t seed, int pixels, SampleStats& stats) {
    const int K = scene.settings.maxDepth + 1;  // path lengths 1 .. K
    const int perLength = std::max(1, (std::max(1, settings_.bootstrapPerPixel) * pixels + K - 1) / K);
    const uint64_t cameraSeed = mix64(seed ^ kBootCameraTag), lightSeed = mix64(seed ^ kBootLightTag);
    // Seed sample j: length k = j / perLength + 1, its streams from generators of j; its pairs
    // (u, s), s = 0 .. k, at I[first[k] + (j mod perLength) (k + 1) + s].
    std::vector<size_t> first(size_t(K) + 2, 0);
    for (int k = 1; k <= K; ++k) first[size_t(k + 1)] = first[size_t(k)] + size_t(perLength) * size_t(k + 1);
    std::vector<float> I(first[size_t(K) + 1], 0.0f);
    runTasks(TaskLoop(K * perLength, cameraSeed, 0), stats, [&](int j, Rng& camera, Task& task) {
        thread_local SubpathPair paths;
        const int k = j / perLength + 1;
        Rng light = taskRng(lightSeed, 0, uint32_t(j));
        traceSubpaths(scene, k, camera, light, paths);
        float* pairs = &I[first[size_t(k)] + size_t(j % perLength) * size_t(k + 1)];
        for (int s = 0; s <= k; ++s) pairs[s] = evaluateTarget(scene, paths, k, s, task.stats).I;
    });

    // b_k's spread (over the seed samples: a seed's k + 1 pairs are not independent), and the
    // chains of each length: one per lit length, the rest in proportion to b_k.
    lengths_.assign(size_t(K), PathLength{});
    std::vector<double> mean(size_t(K), 0.0);
    double total = 0.0;
    int lit = 0;
    for (int k = 1; k <= K; ++k) {
        PathLength& l = lengths_[size_t(k - 1)];
        l.k = k;
        l.seeds = perLength;
        double sum = 0.0, sq = 0.0;
        for (int i = 0; i < perLength; ++i) {
            double v = 0.0;  // the seed's mean over its techniques
            for (int s = 0; s <= k; ++s) v += I[first[size_t(k)] + size_t(i) * size_t(k + 1) + size_t(s)];
            v /= double(k + 1);
            sum += v;
            sq += v * v;
        }
        mean[size_t(k - 1)] = sum / perLength;
        const double var = perLength > 1 ? std::max(0.0, (sq - sum * sum / perLength) / (perLength - 1)) : 0.0;
        l.bStdError = std::sqrt(var / perLength);
        total += mean[size_t(k - 1)];
        lit += mean[size_t(k - 1)] > 0.0;
    }
    chains_.clear();
    scale_.clear();
    stepsPerChain_ = 0;
    if (!(total > 0.0)) return;  // nothing to see (or the TODOs)
    const int wanted = settings_.chains > 0 ? settings_.chains : std::max(1, pixels / 64);
    const int extra = std::max(wanted, lit) - lit;
    std::vector<double> remainder(size_t(K), -1.0);
    int given = 0;
    for (int k = 1; k <= K; ++k) {
        const double share = extra * mean[size_t(k - 1)] / total;
        if (!(mean[size_t(k - 1)] > 0.0)) continue;
        lengths_[size_t(k - 1)].chains = 1 + int(share);
        given += int(share);
        remainder[size_t(k - 1)] = share - std::floor(share);
    }
    for (; given < extra; ++given) {  // the largest remainders, the shorter length first on ties
        const size_t k = size_t(std::max_element(remainder.begin(), remainder.end()) - remainder.begin());
        ++lengths_[k].chains;
        remainder[k] = -1.0;
    }

    // Each length's b_k and the pairs its chains start from (Eq. 9.15).
    std::vector<int> startOf, techniqueOf, lengthOf;  // per chain: its seed sample, s, k
    const uint64_t pickSeed = mix64(seed ^ kPickTag);
    for (PathLength& l : lengths_) {
        if (l.chains == 0) continue;
        const std::vector<float> Ik(I.begin() + ptrdiff_t(first[size_t(l.k)]),
                                    I.begin() + ptrdiff_t(first[size_t(l.k + 1)]));
        Rng pick = taskRng(pickSeed, 0, uint32_t(l.k));
        const Bootstrap boot = bootstrapChains(Ik, l.chains, pick);
        l.b = boot.b;
        if (boot.starts.size() != size_t(l.chains) || !(l.b > 0.0)) {  // the TODO
            l.chains = 0;
            continue;
        }
        for (uint32_t q : boot.starts) {
            startOf.push_back((l.k - 1) * perLength + int(q) / (l.k + 1));
            techniqueOf.push_back(int(q) % (l.k + 1));
            lengthOf.push_back(l.k);
        }
    }
    const int chains = int(startOf.size());
    if (chains == 0) return;
    stepsPerChain_ = (pixels + chains - 1) / chains;
    chains_.resize(size_t(chains));
    scale_.resize(size_t(chains));
    // Chain c's first state: its seed sample, replayed (a large step reads every coordinate
    // afresh, in order, from the same generators).
    runTasks(TaskLoop(chains, cameraSeed, 1), stats, [&](int c, Rng&, Task& task) {
        MultiplexedChain& chain = chains_[size_t(c)];
        const int j = startOf[size_t(c)], k = lengthOf[size_t(c)];
        const PathLength& l = lengths_[size_t(k - 1)];
        scale_[size_t(c)] = l.b * double(pixels) / (double(l.chains) * double(stepsPerChain_));
        chain.k = k;
        chain.s = techniqueOf[size_t(c)];
        chain.camera = PrimarySamples(taskRng(cameraSeed, 0, uint32_t(j)));
        chain.light = PrimarySamples(taskRng(lightSeed, 0, uint32_t(j)));
        chain.camera.startProposal(true);
        chain.light.startProposal(true);
        Rng cameraReplay, lightReplay;  // the chain's first state, read as two random streams
        cameraReplay.replayFrom(&chain.camera);
        lightReplay.replayFrom(&chain.light);
        traceSubpaths(scene, k, cameraReplay, lightReplay, chain.paths);
        chain.current = evaluateTarget(scene, chain.paths, k, chain.s, task.stats);
        chain.camera.accept();
        chain.light.accept();
    });
}

void MMLT::renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out, SampleStats& stats) {
    const int pixels = out.width * out.height;
    if (iteration == 0) start(scene, seed, pixels, stats);
    if (chains_.empty()) return;
    const int chains = int(chains_.size());
    SplatBuffer splats(out.width, out.height, size_t(taskCount(chains)));
    const uint64_t cameraSeed = mix64(seed ^ kCameraTag), lightSeed = mix64(seed ^ kLightTag);
    TaskLoop loop(chains, seed, iteration);
    loop.splats = &splats;
    runTasks(loop, stats, [&](int c, Rng& rng, Task& task) {
        MultiplexedChain& chain = chains_[size_t(c)];
        chain.camera.setRng(taskRng(cameraSeed, iteration, uint32_t(c)));
        chain.light.setRng(taskRng(lightSeed, iteration, uint32_t(c)));
        const float scale = float(scale_[size_t(c)]);  // Eq. 9.16: b_k pixels / M_k
        const SubpathTracer trace = [&](Rng& camera, Rng& light, SubpathPair& paths) {
            traceSubpaths(scene, chain.k, camera, light, paths);
        };
        const TechniqueTarget target = [&](const SubpathPair& paths, int s) {
            return evaluateTarget(scene, paths, chain.k, s, task.stats);
        };
        const SplatFunction splat = [&](const Vec2& raster, const Color& col) { task.splat.add(raster, col * scale); };
        for (int i = 0; i < stepsPerChain_; ++i) mmltStep(chain, settings_.mutations, rng, trace, target, splat);
    });
    splats.resolve(out);
}

namespace {
// The registered "mmlt": the settings above, and what lesson 7's bpt leaves out (the same
// techniques: t = 0 is never chosen, the others are pruned as in connectTechnique).
struct MMLTIntegrator : MMLT {
    std::vector<std::string> leftOut(const Scene& scene) const override { return bptLeftOut(scene, BptOptions{}); }
};
}  // namespace

PS_REGISTER_INTEGRATOR(MMLTIntegrator, "mmlt",
                       "multiplexed Metropolis light transport over the techniques of bpt (lesson 9)");

}  // namespace ps
