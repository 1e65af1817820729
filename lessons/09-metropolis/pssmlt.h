// Lesson 9's Metropolis light transport in primary sample space (Kelemen et al. 2002) over lesson
// 3's path tracer: the chain's state is the vector of uniform numbers the path tracer draws (its
// primary samples), replayed through the unchanged path tracer by an Rng that reads them
// (framework/rng.h, Rng::replayFrom). Small steps perturb every number a little (Eq. 9.9), large
// steps draw them all afresh; the chain targets the path's luminance I (Eq. 9.7) and splats both
// the current and the proposed path (expected values, Eq. 9.5, 9.11); the bootstrap estimates
// b, the integral of I, from many independent paths and picks where the chains start (Eq. 9.10).
// Implemented in solutions/09-metropolis/*.cpp (reference) or assignments/09-metropolis/*.cpp
// (yours); lessons/09-metropolis/README.md derives every formula (Eq. 9.7-9.11).
#pragma once
#include <cstdint>
#include <functional>
#include <vector>
#include "integrator.h"
#include "rng.h"

namespace ps {

// Kelemen's small step (Eq. 9.9): a perturbation of size between s1 and s2, exponentially
// distributed in between (most steps small, some large).
constexpr float kSmallStepMin = 1.0f / 1024.0f;  // s1
constexpr float kSmallStepMax = 1.0f / 64.0f;    // s2

// One small step of a primary sample v in [0, 1) (Eq. 9.9): size s2 exp(-ln(s2 / s1) uSize),
// added if uSign < 1/2, subtracted otherwise, and wrapped around into [0, 1) (the primary sample
// space is a torus: the step is symmetric, T(v -> w) = T(w -> v)). Never returns 1.
float smallStep(float v, float uSize, float uSign);

// The state of one chain: a vector of primary samples u_0, u_1, ... of any length (a path uses as
// many as it draws), read in order by next() while the path tracer evaluates a proposal, and
// mutated LAZILY: a coordinate is brought up to date only when a path reads it, by applying the
// steps it missed since it was last touched (time stamps: the number of the proposal, Eq. 9.9).
class PrimarySamples : public UniformSource {
public:
    // `rng` draws the fresh values of large steps and the numbers of small steps.
    explicit PrimarySamples(const Rng& rng = Rng()) : rng_(rng) {}
    void setRng(const Rng& rng) { rng_ = rng; }

    // Begins proposal number time() + 1: a large step (every coordinate drawn afresh) or a small
    // step (every coordinate one smallStep from its current value); next() reads from 0 again.
    void startProposal(bool largeStep);
    // Coordinate index() of the proposal, brought up to date first; then index() + 1.
    float next() override;
    // Keep the proposal (a large one becomes the time of the last large step), or go back to the
    // state before it, exactly (values and time stamps), and to the time before it.
    void accept();
    void reject();

    // For the tests: the time (number of the current proposal), how many coordinates exist, and
    // coordinate i's value as stored (not brought up to date).
    int64_t time() const { return time_; }
    size_t size() const { return x_.size(); }
    float stored(size_t i) const { return x_[i].value; }
    size_t index() const { return index_; }

private:
    struct Coordinate {
        float value = 0.0f, backup = 0.0f;
        int64_t modified = 0, modifiedBackup = 0;  // the time at which value was last changed
    };
    std::vector<Coordinate> x_;
    Rng rng_;
    int64_t time_ = 0;           // the current proposal's number
    int64_t lastLargeStep_ = 0;  // the time of the last accepted large step
    bool largeStep_ = true;
    size_t index_ = 0;  // the next coordinate next() reads
};

// A path in primary sample space: where it lands on the image and what it carries.
struct PathSample {
    Vec2 raster;     // raster position: (u_0 width, u_1 height)
    Color L;         // the path tracer's radiance estimate f for these primary samples
    float I = 0.0f;  // the scalar contribution the chain targets: luminance(L) (Eq. 9.7)
};
// Evaluates the path of the numbers `replay` gives (an Rng replaying a PrimarySamples).
using PathEvaluator = std::function<PathSample(Rng& replay)>;
// Adds colour c at a raster position (the integrator scales it by b / mutations per pixel).
using SplatFunction = std::function<void(const Vec2& raster, const Color& c)>;

// The bootstrap (Eq. 9.10): from the contributions I[i] of n independent seed paths, b = their
// mean, and for each of `chains` chains the index of the seed path it starts from, chosen with
// probability I[i] / sum(I): chain c inverts the discrete CDF of I at (c + rng.uniform()) / chains
// (stratified), lowest index whose CDF exceeds it. With sum(I) = 0: b = 0 and no chains.
struct Bootstrap {
    double b = 0.0;
    std::vector<uint32_t> starts;
};
Bootstrap bootstrapChains(const std::vector<float>& I, int chains, Rng& rng);

// One chain: its primary samples and the path they give now (current.I > 0).
struct Chain {
    PrimarySamples samples;
    PathSample current;
};

// One Metropolis step of a chain (Eq. 9.11): a large step if rng.uniform() < pLarge, else a small
// one; the proposal's path y = evaluate(an Rng replaying chain.samples); a = min(1, I(y) / I(x));
// splat x's colour weighted (1 - a) / I(x) and y's weighted a / I(y) (expected values, Eq. 9.5);
// then accept if rng.uniform() < a. Returns a.
float mltStep(Chain& chain, float pLarge, Rng& rng, const PathEvaluator& evaluate, const SplatFunction& splat);

// The integrator "pssmlt" (lessons/09-metropolis/pssmlt_integrator.cpp): at iteration 0 the
// bootstrap (bootstrapPerPixel seed paths per pixel), then every iteration as many steps as the
// image has pixels, shared by the chains (each chain a task item: thread-count independent).
struct MLTSettings {
    float pLarge = 0.3f;         // large-step probability
    int chains = 0;              // 0: one chain per 64 pixels (at least 1)
    int bootstrapPerPixel = 16;  // seed paths per pixel for b and the chains' starts
};
class PSSMLT : public Integrator {
public:
    explicit PSSMLT(const MLTSettings& settings = MLTSettings()) : settings_(settings) {}
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override;
    // After iteration 0: the bootstrap's b, the number of chains and of steps per iteration.
    double b() const { return b_; }
    int chains() const { return int(chains_.size()); }
    int64_t stepsPerIteration() const { return int64_t(chains_.size()) * stepsPerChain_; }

    // The path of lesson 3's path tracer (LiMIS, the scene's maximum depth) for the numbers of
    // `replay`: raster from the first two, then the camera ray and the walk. A non-finite
    // radiance is counted in stats and gives I = 0.
    static PathSample evaluatePath(const Scene& scene, Rng& replay, SampleStats& stats);

private:
    void start(const Scene& scene, uint64_t seed, int pixels, SampleStats& stats);
    MLTSettings settings_;
    std::vector<Chain> chains_;
    double b_ = 0.0;
    int stepsPerChain_ = 0;
};

}  // namespace ps
