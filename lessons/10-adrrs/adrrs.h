// Lesson 10's adjoint-driven Russian roulette and splitting (ADRRS, Vorba and Křivánek 2016) inside
// lesson 3's path tracer: a short path-traced pre-pass fills a cache with the radiance a path
// collects from each vertex on (the adjoint of the path tracer's importance transport, Eq. 10.1,
// 10.8); at every vertex the walk compares the path's expected contribution with the pixel's (the
// weight window, Eq. 10.2, 10.5-10.7, 10.9) and goes on with an expected number q of
// continuations, each weighted beta / q (Eq. 10.3, 10.4): q < 1 is Russian roulette, q > 1
// splitting. Implemented in
// solutions/10-adrrs/*.cpp (reference) or assignments/10-adrrs/*.cpp (yours);
// lessons/10-adrrs/README.md derives every formula (Eq. 10.1-10.9, Algorithm 10.1).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>
#include "03-path-tracing/pathtracer.h"
#include "integrator.h"

namespace ps {

// ---------------------------------------------------------------------------------------------
// The adjoint cache (Eq. 10.8): the scene's bounding box cut into kCacheResolution^3 cells, each
// with kCacheSides direction bins (the side of a surface the path sees: six, one per signed axis).
// An entry's estimate is the mean of the pre-pass's samples there; ADRRS trusts it only where it is
// reliable: a mean above 0 known to within kMaxRelativeError (the relative standard error, as the
// paper does with 30 %). Elsewhere (no light seen yet, or seen by too few samples) lesson 3's
// roulette decides.
constexpr int kCacheResolution = 8;
constexpr int kCacheSides = 6;
constexpr float kMaxRelativeError = 0.3f;

class AdjointCache {
public:
    AdjointCache() = default;
    // An empty cache over `bounds` (the scene's bounding box) with resolution^3 cells.
    explicit AdjointCache(const AABB& bounds, int resolution = kCacheResolution);

    int resolution() const { return res_; }
    const AABB& bounds() const { return bounds_; }
    // The number of entries: cells times sides.
    int entries() const { return int(count_.size()); }

    // The cell of point p: per axis i = floor(resolution (p - lo) / (hi - lo)), clamped to
    // [0, resolution - 1] (a point on the box's far face, or just outside it by rounding, lands
    // in the last cell); flattened as ix + resolution (iy + resolution iz). An axis along which
    // the box is flat (hi = lo) has i = 0.
    int cell(const Vec3& p) const;
    // The direction bin of a vertex with surface normal n seen from direction wo (towards the
    // previous vertex): the normal turned to wo's side (-n if dot(n, wo) < 0), then its
    // dominant axis a (0, 1, 2 = x, y, z; the first of equal ones) and sign: 2a for +, 2a + 1 for -.
    static int side(const Vec3& n, const Vec3& wo);
    // The entry of a vertex at p with normal n, seen from wo: cell(p) * kCacheSides + side(n, wo).
    int entry(const Vec3& p, const Vec3& n, const Vec3& wo) const { return cell(p) * kCacheSides + side(n, wo); }

    // Adds one sample (the pre-pass, Eq. 10.8) to an entry.
    void add(int entry, const Color& value);
    // An entry's estimate: the mean of its samples (black without one).
    Color estimate(int entry) const { return mean_[size_t(entry)]; }
    uint32_t samples(int entry) const { return count_[size_t(entry)]; }
    // The relative standard error of an entry's estimate (of the mean of its channels): sqrt(s^2 /
    // n) / mean; +infinity with fewer than 2 samples or a mean of 0; 0 for an entry set().
    float relativeError(int entry) const;
    // Whether ADRRS may use the entry: relativeError(entry) <= kMaxRelativeError.
    bool reliable(int entry) const { return reliable_[size_t(entry)] != 0; }
    // Sets an entry's estimate outright, as exact (reliable unless black; tests: a deliberately
    // bad cache).
    void set(int entry, const Color& value);
    // The number of reliable entries.
    int reliableEntries() const;

private:
    AABB bounds_;
    int res_ = 0;
    std::vector<DColor> sum_;
    std::vector<double> sumSq_;  // of the mean of each sample's channels
    std::vector<uint32_t> count_;
    std::vector<uint8_t> exact_;     // set() by hand: relative error 0
    std::vector<Color> mean_;        // estimate(), kept up to date by add() and set()
    std::vector<uint8_t> reliable_;  // reliable(), likewise
    void update(int entry);
};

// One vertex of a pre-pass path, as the walk's visitor saw it (the escape included).
struct PrePassVertex {
    int entry = -1;  // the vertex's cache entry; -1 where nothing is cached (the escape, a delta material)
    Color beta;      // the throughput beta_k of the path up to the vertex (Eq. 3.4)
    Color added;     // what the vertex added to the path's estimate (addMISContribution, Eq. 3.7)
};
// One sample for the cache: an entry and a value of the radiance collected from there on.
struct CacheSample {
    int entry = -1;
    Color value;
};
// The pre-pass samples of one path (Eq. 10.8): for every vertex k with an entry, the radiance the
// path collected from x_k on, the sum over j >= k of added_j (x_k's own light sample included),
// divided by beta_k channel by channel (a channel where beta_k is 0 gives 0), appended to `out` in
// the order of the vertices.
void continuationSamples(const std::vector<PrePassVertex>& path, std::vector<CacheSample>& out);

// ---------------------------------------------------------------------------------------------
// The weight window (Eq. 10.5, 10.6).
constexpr float kWindowRatio = 5.0f;                       // s = upper / lower (the paper's value)
constexpr float kMinContinuations = kRouletteMinSurvival;  // q never below (0.05: unbiased for any cache)
constexpr float kMaxContinuations = 8.0f;                  // q never above (at most 8 continuations per vertex)

struct WeightWindow {
    float centre = 0.0f;  // C_ww = I~ / Psi~ (Eq. 10.5)
    float lower = 0.0f;   // delta- = 2 C_ww / (1 + s) (Eq. 10.6)
    float upper = 0.0f;   // delta+ = s delta-
};
// The window of a path at a vertex where the cache predicts Psi~ > 0 from there on, in a pixel
// whose estimate is I~ >= 0 (Eq. 10.5, 10.6); `ratio` is s. Psi~ <= 0 (the cache says the path
// will collect nothing): every bound +infinity.
WeightWindow weightWindow(float pixelEstimate, float adjoint, float ratio = kWindowRatio);
// The expected number of continuations of a path of weight nu >= 0 (Eq. 10.7): nu / delta- below
// the window (roulette), nu / delta+ above it (splitting), 1 inside it (bounds included); then
// clamped to [kMinContinuations, kMaxContinuations].
float expectedContinuations(float weight, const WeightWindow& window);

// ---------------------------------------------------------------------------------------------
// The ADRRS decision at a vertex (Eq. 10.2-10.7).

// The pixel estimate I~ of a camera ray (Eq. 10.9): the mean over the colour channels of what the
// cache predicts the camera path collects from its first vertex x0 on (the camera ray's own
// vertex, bounces 0); -1 where the cache has no reliable estimate for x0 (a miss, a delta
// material, an entry that is not reliable): that camera ray plays lesson 3's roulette throughout.
float pixelEstimate(const AdjointCache& cache, const Scene& scene, const WalkVertex& x0);

// q at vertex v of a camera path whose pixel estimate is I~ (Eq. 10.2, 10.5-10.7): with the
// cache's Psi~ (a colour) for v, the path's weight nu = sum_c beta_c Psi~_c / sum_c Psi~_c (nu Psi~
// is the path's expected contribution, Eq. 10.2) and Psi~ as one number, the mean of its channels;
// Psi~ black: nu = the mean of beta's channels. Where ADRRS cannot decide (I~ < 0, a delta
// material, an entry that is not reliable) it returns kNoDecision: the walk's own roulette, lesson
// 3's, plays after the bounce, exactly as in pt.
constexpr float kNoDecision = 0.0f;
float adrrsContinuations(const AdjointCache& cache, const Scene& scene, const WalkVertex& v, float pixelEstimate);

// ---------------------------------------------------------------------------------------------
// Survival and splitting (Eq. 10.3, 10.4) and the walk that branches (Algorithm 10.1).

// How a path goes on from a vertex: lesson 3's Continuations (n continuations, each with
// throughput beta), drawn from the expected number q. Eq. 10.3, 10.4: n = floor(q) + 1 with probability q - floor(q), else floor(q), so E[n] = q; each
// continuation carries beta / q. Draws one rng.uniform() (n = floor(q) + 1 if it is below
// q - floor(q)) only when q is not a whole number. q > 0.
Continuations continuations(const Color& beta, float q, Rng& rng);

// The rule ADRRS asks at each vertex the walk may go on from: the expected number of continuations q.
using ExpectedContinuations = std::function<float(const WalkVertex& v)>;

// Once a camera ray's walk has started this many paths (1 + the extra continuations of every
// split), q is cut to min(q, 1) (roulette still plays: unbiased, and bounded work). The split just
// before can still start kMaxContinuations - 1 more: at most 31 + 7 = 38 paths (README 1.3).
constexpr int kMaxPathsPerCameraRay = 32;

// The walk with survival and splitting (Algorithm 10.1): lesson 3's camera walk (with lesson 3's
// roulette) and a continuation rule (Eq. 3.10): at a vertex x_k it may go on from (hit, visited
// with true, bounces < maxDepth) the rule asks q = expected(v); kNoDecision leaves x_k to the walk
// (one continuation with v.beta, lesson 3's roulette after its bounce); else (q = min(q, 1) if
// kMaxPathsPerCameraRay paths have been started) it draws the continuations (continuations(v.beta,
// q, rng)), without the walk's roulette after their bounces. The walk follows each continuation to its end
// before the next one samples its BSDF: depth first, so the numbers come from `rng` in one fixed
// order. Every vertex of the tree is visited (the escapes included), in that order.
void splittingWalk(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth, const ExpectedContinuations& expected,
                   const WalkVisitor& visit);

// ---------------------------------------------------------------------------------------------
// The integrator "pt-adrrs" (lessons/10-adrrs/adrrs_integrator.cpp): at iteration 0 the pre-pass
// (ADRRSSettings' number of paths of lesson 3's pt, recorded by continuationSamples), then every
// iteration one camera ray per pixel through splittingWalk with adrrsContinuations and lesson 3's
// addMISContribution as the visitor.
enum class Roulette {
    ADRRS,    // adrrsContinuations and splittingWalk: pt-adrrs
    Classic,  // lesson 3's cameraWalk and roulette: the same estimator as pt (counted, for comparisons)
};
struct ADRRSSettings {
    Roulette roulette = Roulette::ADRRS;
    int prePassPerPixel = 8;       // pre-pass paths per pixel ...
    int prePassMinimum = 1 << 14;  // ... but at least this many in all (small test images)
    int resolution = kCacheResolution;
};

// What a render counted (over all its iterations, the pre-pass not included). A vertex is a ray's
// end, the escapes included; it is wasted when neither it nor any vertex after it on its branch
// adds anything to the image (the ray that reached it, and its light sample, bought nothing).
struct PathCounts {
    uint64_t cameraRays = 0, vertices = 0, wasted = 0;
    uint64_t decisions = 0;  // times the rule decided (ADRRS only; not where it left it to lesson 3's roulette)
    uint64_t roulette = 0;   // ... and the rule said q < 1
    uint64_t splits = 0;     // ... and the rule said q > 1
    PathCounts& operator+=(const PathCounts& o);
};

class ADRRSPathTracer : public Integrator {
public:
    explicit ADRRSPathTracer(const ADRRSSettings& settings = ADRRSSettings()) : settings_(settings) {}
    // Use this cache instead of the pre-pass's (tests: a deliberately bad one); call before rendering.
    void useCache(const AdjointCache& cache) {
        cache_ = cache;
        haveCache_ = true;
    }
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override;
    std::vector<std::string> report() const override;

    const AdjointCache& cache() const { return cache_; }
    const PathCounts& counts() const { return counts_; }

    // One camera ray's radiance estimate, counted into `counts`.
    Color Li(const Scene& scene, const Ray& ray, Rng& rng, PathCounts& counts) const;

    // The pre-pass's cache for a scene (Eq. 10.8): `paths` paths of lesson 3's pt (path i through
    // pixel i mod pixels), each from its own generator (seeded by `seed`), their samples added in
    // a fixed order (thread-count independent).
    static AdjointCache prePass(const Scene& scene, int paths, int resolution, uint64_t seed, SampleStats& stats);

private:
    ADRRSSettings settings_;
    AdjointCache cache_;
    bool haveCache_ = false;
    uint64_t prePassPaths_ = 0;
    PathCounts counts_;
};

}  // namespace ps
