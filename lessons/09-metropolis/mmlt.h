// Lesson 9's multiplexed Metropolis light transport (Hachisuka et al. 2014) over lesson 7's
// bidirectional path tracer: the chain's state is a point of primary sample space AND one of
// BPT's techniques (s, t) of a fixed path length k. The target is that technique's MIS-weighted
// contribution divided by the probability of choosing the technique (Eq. 9.12), so the chain
// spends its time on the technique that samples each path best. Three mutations (Eq. 9.13):
// large steps (new numbers, a new technique), small steps (Kelemen's, the technique kept) and
// the technique mutation (the numbers kept, a neighbouring technique), each accepted with
// Eq. 9.2 and splatted with expected values (Eq. 9.14); chains per path length, each length
// with its own b_k from a bootstrap of its own (Eq. 9.15, 9.16).
//
// Implemented in solutions/09-metropolis/{mmlt_target,technique_mutation,mmlt_step}.cpp
// (reference) or assignments/09-metropolis/ (yours); lessons/09-metropolis/mmlt_integrator.cpp is
// the plumbing; lessons/09-metropolis/README.md, section 1.11, derives every formula.
// Reused: lesson 7's subpaths, connections and MIS weights; lesson 9's PrimarySamples (one per
// stream), acceptance (Eq. 9.2, with the transition probabilities of the technique mutation),
// bootstrapChains (per path length) and the splats of PSSMLT (PathSample, SplatFunction).
#pragma once
#include <functional>
#include <vector>
#include "07-bidirectional/bpt.h"
#include "09-metropolis/metropolis1d.h"
#include "09-metropolis/pssmlt.h"

namespace ps {

// The subpaths of one point of primary sample space, for a chain of path length k (Eq. 9.12).
// Two streams of primary samples: the camera stream gives the raster position (its first two
// numbers) and then the camera subpath z_0 z_1 ... (at most k + 1 vertices); the light stream
// gives the light sample of the s = 1 technique (three numbers) and then the light subpath
// y_0 y_1 ... (at most k vertices). Every technique (s, k + 1 - s), s = 0 .. k, is evaluated on
// the same pair: a change of technique keeps the subpaths.
struct SubpathPair {
    Vec2 raster;          // (u_0 width, u_1 height): the camera subpath's raster position
    float uLight = 0.0f;  // the s = 1 technique's light (scene.selectLight) and point on it
    Vec2 uPos;
    Subpath camera, light;
};

// ---- plumbing (mmlt_integrator.cpp) ----

// The pair of path length k from the two streams: raster, lesson 7's cameraSubpath (maximum
// depth k - 1: up to k + 1 vertices), the three numbers of the light sample, lesson 7's
// lightSubpath (maximum depth k - 1: up to k vertices), both with the power heuristic's partial
// sums.
void traceSubpaths(const Scene& scene, int k, Rng& cameraStream, Rng& lightStream, SubpathPair& out);

// Technique (s, t) on the pair: lesson 7's connect (with the pair's light sample for s = 1) and
// its reverse pdfs; not valid where the subpaths are too short for it (roulette or a miss ended
// them), or where the connection would sit on a specular vertex (0 anyway, Eq. 7.12).
Connection connectTechnique(const Scene& scene, const SubpathPair& paths, int s, int t);

// ---- the target (mmlt_target.cpp), Eq. 9.12 ----

// p_k(s): the probability with which a large step (and the bootstrap) chooses technique s among
// the k + 1 techniques (s, k + 1 - s), s = 0 .. k, of path length k: uniform, 1 / (k + 1).
// (t = 0 is not among them: no path hits the pinhole, Eq. 7.12.)
float techniqueProbability(int k);

// The technique chosen with one uniform number u in [0, 1): s = floor(u (k + 1)), at most k.
int selectTechnique(int k, float u);

// The chain's target at technique s of path length k on `paths` (Eq. 9.12): technique (s, t =
// k + 1 - s)'s unweighted contribution C*_{s,t} (connectTechnique) times its MIS weight w_{s,t}
// (lesson 7's misWeightRecursive, power heuristic), divided by p_k(s). t >= 2 lands at
// paths.raster; t = 1 where the light vertex lands (the connection's raster), also divided by
// width * height (lesson 5's splat factor, Eq. 7.11). I = luminance(L), at least 0. An invalid
// connection: L = 0, I = 0 at paths.raster.
PathSample multiplexedTarget(const Scene& scene, const SubpathPair& paths, int k, int s);

// ---- the technique mutation (technique_mutation.cpp), Eq. 9.13 ----

// From technique s of path length k (0 <= s <= k, k >= 1), a neighbour s' within 0 .. k: from
// an end (s = 0 or s = k) its only neighbour, else s - 1 if u < 1/2 and s + 1 otherwise. Returns
// y = s' with T(s -> s') = 1 / (number of neighbours of s) in Txy and T(s' -> s) = 1 / (number of
// neighbours of s') in Tyx: not symmetric next to the ends (k >= 2).
Proposal mutateTechnique(int s, int k, float u);

// ---- one step (mmlt_step.cpp), Eq. 9.14 ----

// A chain of path length k: one PrimarySamples per stream, the technique s, the subpaths of the
// current state and what the target gives there (current.I > 0).
struct MultiplexedChain {
    PrimarySamples camera, light;  // the camera and the light stream
    int k = 1, s = 0;
    SubpathPair paths;     // the current state's subpaths
    SubpathPair proposed;  // where a large or small step traces its proposal's subpaths
    PathSample current;    // the target at (paths, s)
};

// A technique mutation with probability pTechnique, else a large step with probability pLarge,
// else a small step.
struct MMLTMutations {
    float pLarge = 0.3f;
    float pTechnique = 0.2f;
};

// Traces the subpaths of the numbers the two replaying Rngs give (traceSubpaths in the
// integrator; the tests use their own).
using SubpathTracer = std::function<void(Rng& cameraStream, Rng& lightStream, SubpathPair& out)>;
// The target of technique s on a pair (multiplexedTarget in the integrator).
using TechniqueTarget = std::function<PathSample(const SubpathPair& paths, int s)>;

// One Metropolis step of a multiplexed chain (Eq. 9.14): uKind = rng.uniform() picks the mutation.
//   technique (uKind < pTechnique): p = mutateTechnique(s, k, rng.uniform()); the proposal is
//       (the same subpaths, s' = p.y): y = target(chain.paths, s'); a = acceptance(I(x), I(y), p).
//   large (uKind < pTechnique + pLarge) or small: both streams startProposal(large); s' =
//       selectTechnique(k, rng.uniform()) for a large step, s for a small one; trace the
//       proposal's subpaths into chain.proposed from Rngs replaying the two streams; y =
//       target(chain.proposed, s'); a = min(1, I(y) / I(x)).
// Splat x's colour weighted (1 - a) / I(x) and y's weighted a / I(y) (expected values, only
// weights > 0); then accept if rng.uniform() < a (the state, the technique, the subpaths and both
// streams), else reject (both streams). Returns a.
float mmltStep(MultiplexedChain& chain, const MMLTMutations& m, Rng& rng, const SubpathTracer& trace,
               const TechniqueTarget& target, const SplatFunction& splat);

// ---- the integrator "mmlt" (plumbing, mmlt_integrator.cpp), Eq. 9.15, 9.16 ----

struct MMLTSettings {
    MMLTMutations mutations;
    int chains = 0;              // 0: one per 64 pixels; always at least one per lit path length
    int bootstrapPerPixel = 16;  // seed samples per pixel, shared equally by the path lengths (each
                                 // seed's subpaths evaluated with all k + 1 techniques)
};

// What the bootstrap found for path length k (after iteration 0).
struct PathLength {
    int k = 0;
    double b = 0.0;          // b_k: the mean target luminance of its seed samples' pairs (u, s) (Eq. 9.15)
    double bStdError = 0.0;  // the standard error of b_k (from the seed samples' means over s)
    int seeds = 0;           // its seed samples
    int chains = 0;          // its chains
};

class MMLT : public Integrator {
public:
    explicit MMLT(const MMLTSettings& settings = MMLTSettings()) : settings_(settings) {}
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override;
    const std::vector<PathLength>& lengths() const { return lengths_; }
    // The sum of the b_k: the image's mean luminance (Eq. 9.16).
    double b() const;
    int chains() const { return int(chains_.size()); }

private:
    void start(const Scene& scene, uint64_t seed, int pixels, SampleStats& stats);
    MMLTSettings settings_;
    std::vector<PathLength> lengths_;
    std::vector<MultiplexedChain> chains_;
    std::vector<double> scale_;  // per chain: b_k pixels / M_k, its length's splat factor
    int stepsPerChain_ = 0;
};

}  // namespace ps
