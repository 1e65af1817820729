// Lesson 8's photon mapping (Jensen's two-pass method): photons traced from the lights on
// lesson 5's light walk with a Russian roulette that keeps every photon's power at Phi / N
// (Eq. 8.1-8.3), stored at non-specular hits in a caustic map (paths L S+ D) and a global map;
// each map is a left-balanced kd-tree kept in one array in heap order (Eq. 8.4), searched for
// the k nearest photons with a bounded max-heap or for every photon within a radius (Eq. 8.5);
// the radiance leaving a surface point is a density estimate over those photons with the box,
// cone or Gaussian filter (Eq. 8.6-8.10); the `pm` integrator adds direct light (next-event
// estimation), caustics from the caustic map and indirect light by final gathering into the
// global map (Eq. 8.11), and Ward's irradiance cache as its fast final gather (Eq. 8.15-8.18);
// the `ppm` integrator shrinks a fixed search radius from pass to pass (Knaus and Zwicker's
// progressive photon mapping, Eq. 8.13-8.14), so its image converges. Implemented in
// solutions/08-photon-mapping/*.cpp (reference) or assignments/08-photon-mapping/*.cpp (yours);
// lessons/08-photon-mapping/README.md derives every formula (Eq. 8.1-8.18).
#pragma once
#include <cstdint>
#include <functional>
#include <vector>
#include "05-light-tracing/lighttracer.h"

namespace ps {

// ---- the photon (framework of this lesson: photon_map.cpp) ----

// One stored photon: 32 bytes. The direction it arrived from is kept in 2 x 16 bits
// (octahedral encoding, error below 1e-4 rad).
struct Photon {
    Vec3 p;                    // where it landed
    Color power;               // Delta Phi, its power in watts (Eq. 8.2)
    uint16_t dir[2] = {0, 0};  // wLight, unit, back towards where it came from (encodeDirection)
    uint8_t population = 0;    // the class a photon visitor sorts it into (its path's vertex types,
                               // say); pm has one: 0
    Vec3 wLight() const;       // decodes dir
    void setWLight(const Vec3& w);
};

// ---- the kd-tree (kdtree.cpp, Eq. 8.4): over any set of points ----

// A left-balanced kd-tree over a set of points, in arrays in heap order (Eq. 8.4): node i (1 ..
// size()) holds the point p[i], its index item[i] in the set the tree was built from, and the
// axis it splits on (0 x, 1 y, 2 z); the root is node 1; the children of node i are 2i and 2i + 1
// when those are <= size(); index 0 is unused; no pointers. A left-balanced tree of n points fills
// nodes 1 .. n exactly. The photon map is one (PhotonMap); any algorithm that looks points up by
// position (light vertices near a camera vertex, say) builds its own.
struct KdTree {
    std::vector<Vec3> p;
    std::vector<uint32_t> item;
    std::vector<uint8_t> axis;
    size_t size() const { return p.empty() ? 0 : p.size() - 1; }
};

// The number of nodes in the left subtree of a left-balanced binary tree of n >= 1 nodes
// (every level full but the last, whose nodes are packed to the left).
size_t leftSubtreeSize(size_t n);

// Builds the left-balanced kd-tree of the points (any order) in O(n log n): each node splits its
// points on the axis of largest extent of their bounding box, at the median that makes its left
// subtree leftSubtreeSize(n) points (std::nth_element), the median point goes to the node (axis
// set), those with a smaller or equal coordinate to its left subtree (node 2i), the rest to its
// right (2i + 1). Fills tree's arrays (size n + 1).
void buildKdTree(const std::vector<Vec3>& points, KdTree& tree);

// ---- queries (kdtree_query.cpp, Eq. 8.5) ----

// A point found by a query: its node (an index into the tree's arrays) and its squared distance
// to the query point, |p - x|^2 computed as photonDistance2 does.
struct NearPhoton {
    uint32_t node = 0;
    float d2 = 0.0f;
};
inline float photonDistance2(const Vec3& p, const Vec3& x) { return glm::dot(p - x, p - x); }
// Orders a max-heap of NearPhoton by d2 (std::push_heap / std::pop_heap with this comparison:
// the farthest point on top, at found[0]).
inline bool nearerPhoton(const NearPhoton& a, const NearPhoton& b) { return a.d2 < b.d2; }

// One search of the tree serves both queries (Eq. 8.5): it keeps a bound on d2, descends first
// into the child on x's side of the splitting plane and visits the other child only if the squared
// distance from x to the plane is <= the bound at that moment, and hands every point it visits
// with d2 <= the bound to a visitor, which may lower the bound (never raise it) to shrink the rest
// of the search: a fixed-radius query leaves it, the k-nearest query lowers it to its k-th
// distance (Jensen's way).
using PointVisitor = std::function<void(uint32_t node, float d2, float& r2)>;
// Every point with d2 <= the bound, r2 at first and then whatever visit leaves in its third
// argument, each handed to visit (in the order the search meets them). Returns the number of nodes
// visited (whose point's distance was computed).
int pointsInRadius(const KdTree& tree, const Vec3& x, float r2, const PointVisitor& visit);

// The k nearest points to x with d2 <= maxD2 (Eq. 8.5): found is cleared, then holds
// min(k, number within maxD2) points as a max-heap under nearerPhoton (found[0] the farthest).
// Ties (equal distances) may be broken either way. The search is pointsInRadius from maxD2 whose
// visitor keeps the heap: once it holds k points, a point found replaces its farthest, and the
// bound is the farthest one's d2 (found[0].d2). Returns the number of nodes visited.
int nearestPoints(const KdTree& tree, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found);

// ---- the photon map (plumbing, photon_map.cpp) ----

// A photon map: the kd-tree of the photons' positions, and the photons in its node order:
// nodes[i] is the photon at node i (nodes[0] unused).
struct PhotonMap {
    KdTree tree;
    std::vector<Photon> nodes;
    int emitted = 0;  // N, the photons emitted to make this map (their power is Phi / N)
    size_t size() const { return tree.size(); }
};

// The photons' kd-tree (buildKdTree of their positions, handed to it in a spatial order: sorted by
// cell of a coarse grid, which makes the build's partitions cheaper) and the photons in its node
// order; map.emitted is left as it is.
void buildPhotonMap(std::vector<Photon> photons, PhotonMap& map);
// The k nearest photons (nearestPoints on the map's tree: NearPhoton::node indexes map.nodes).
int nearestPhotons(const PhotonMap& map, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found);
// Every photon with d2 <= r2 (pointsInRadius on the map's tree), in found (cleared first).
int photonsInRadius(const PhotonMap& map, const Vec3& x, float r2, std::vector<NearPhoton>& found);

// ---- filters (filters.cpp, Eq. 8.7-8.10) ----

enum class Filter { Box, Cone, Gaussian };
const char* filterName(Filter f);
// Jensen's constants: the cone's slope k (>= 1) and the Gaussian's alpha and beta (Eq. 8.10).
constexpr float kConeK = 1.1f;
constexpr float kGaussAlpha = 0.918f, kGaussBeta = 1.953f;

// The filter kernel K(d) of Eq. 8.7-8.10 for a photon at squared distance d2 <= r2 from the
// query point: box 1 / (pi r^2), cone (1 - d / (k r)) / ((1 - 2 / (3k)) pi r^2), Gaussian
// alpha [1 - (1 - e^(-beta d^2 / r^2)) / (1 - e^(-beta))] / r^2; each integrates to 1 over the
// disc of radius r (0 for d2 > r2).
float filterKernel(Filter f, float d2, float r2, float coneK = kConeK);

// ---- the radiance estimate (estimate.cpp, Eq. 8.6) ----

struct EstimateOptions {
    Filter filter = Filter::Box;
    int k = 50;              // photons to gather (k-nearest), or 0: every photon within maxRadius
    float maxRadius = 1.0f;  // the search radius (fixed radius when k == 0, else the largest)
    float coneK = kConeK;
};

// The radiance leaving sp towards wo (Eq. 8.6): L = sum over the photons found of
// f(wo, photon.wLight) DeltaPhi K(d), with the material's evalBSDF (a photon arriving from the
// other side of a surface that does not transmit gets f = 0) and K = filterKernel with r^2 the
// largest d2 found when k photons were found (k-nearest), else maxRadius^2. No photon: black.
Color radianceEstimate(const PhotonMap& map, const SurfacePoint& sp, const Material& m, const Vec3& wo,
                       const EstimateOptions& opt);

// ---- photon tracing (photon_tracing.cpp, Eq. 8.1-8.3) ----

// Russian roulette for photons (Eq. 8.3): the particle survives with q = the largest component of
// its throughput since the light (after the bounce's weight), at most 1, from the first bounce
// on. Because the throughput is divided by q, its largest component stays 1: every stored
// photon carries Phi / N (for grey surfaces exactly).
float photonSurvival(const Color& throughput, int bounces);

enum class MapKind { Caustic, Global };

// The photon visitor: what a later algorithm does at every vertex y_k of one photon's walk (y_0
// included), after pm's own decision there: `photon` is the photon about to be stored at y_k
// (nullptr where none is), whose population it may set. Returning false drops that photon and
// ends the walk (nothing after y_k can matter to the algorithm). One visitor serves one walk (it
// may keep the path's state).
using PhotonVisitor = std::function<bool(const WalkVertex& v, Photon* photon)>;

// One photon path (Eq. 8.1-8.3): lesson 5's lightWalk with photonSurvival; at every vertex with
// bounces >= 1 on a non-specular material, a photon (position, power = the particle's beta / N
// with N = emitted, wLight). Global map: every such vertex. Caustic map: only a vertex reached
// from the light through specular bounces alone (L S+ D: bounces >= 2, every earlier surface
// specular); the walk ends there, and at the first non-specular surface in any case. With a
// visitor, each vertex is handed to it last. `continuation` (lesson 3's continuation rule, empty:
// none) is the walk's: a photon path may split, or end at a vertex, by a rule of the caller's; its
// photons carry the power it leaves them. Appends to out.
void tracePhoton(const Scene& scene, Rng& rng, int maxDepth, MapKind kind, int emitted, std::vector<Photon>& out,
                 const PhotonVisitor& visit = nullptr, const ContinuationRule& continuation = {});

// Makes the continuation rule of one photon path (it may keep a count of the path's own).
using PhotonRules = std::function<ContinuationRule()>;

// Traces `emitted` photon paths (path i with taskRng(seed, iteration, i), in parallel tasks,
// photons kept in path order) and builds their map (photon_map.cpp). Bit-identical for any
// number of threads. `rules` (if set) makes every path's continuation rule.
PhotonMap tracePhotonMap(const Scene& scene, MapKind kind, int emitted, int maxDepth, uint64_t seed, uint32_t iteration,
                         SampleStats& stats, const PhotonRules& rules = {});
// The same with a photon visitor (a fresh one per photon path, from newVisitor): one map per
// population, maps[p] holding the photons of population p (in path order; empty where none).
std::vector<PhotonMap> tracePhotonPopulations(const Scene& scene, MapKind kind, int emitted, int maxDepth,
                                              uint64_t seed, uint32_t iteration, SampleStats& stats,
                                              const std::function<PhotonVisitor()>& newVisitor,
                                              const PhotonRules& rules = {});

// ---- the pm integrator (pm.cpp, Eq. 8.11) ----

struct PhotonMaps {
    PhotonMap caustic, global;
};

struct IrradianceCache;

// The gather visitor: a later algorithm's say in pm's camera side (Eq. 8.11), term by term (its
// own photon maps, sorted by population, say). The camera walk reaches the first non-specular
// vertex x through specular bounces alone; each hook sees the vertex its term is taken at, whose
// bounces say how many specular vertices came before. An empty hook leaves pm's term as it is.
struct GatherVisitor {
    std::function<bool(const WalkVertex& v)> emission;                     // whether the emission found at v counts
    std::function<bool(const WalkVertex& x)> lightSample;                  // whether x's light sample counts (its
                                                                           // numbers are drawn either way)
    std::function<Color(const WalkVertex& x, const Material& m)> caustic;  // the caustic estimate at x
    // The estimate at the final gather's non-specular hit y (its bounces yBounces) towards the
    // gather ray, gathered from x (xBounces): the global map's radiance there.
    std::function<Color(const SurfacePoint& x, int xBounces, const SurfacePoint& y, const Material& m, const Vec3& wo,
                        int yBounces)>
        global;
    // Whether the walk goes on past v: through a specular v, or from x to its final gather (false
    // where nothing after v can count for the algorithm).
    std::function<bool(const WalkVertex& v)> goesOn;
    bool countsEmission(const WalkVertex& v) const { return !emission || emission(v); }
    bool countsLightSample(const WalkVertex& x) const { return !lightSample || lightSample(x); }
    bool continuesPast(const WalkVertex& v) const { return !goesOn || goesOn(v); }
};

struct PmOptions {
    EstimateOptions causticEstimate;  // the caustic map's (sharp: few photons, small radius)
    EstimateOptions globalEstimate;   // the global map's, looked up at the final gather's hits
    int maxDepth = 8;
    // Irradiance caching (`pm-ic`, Eq. 8.15-8.18): at a Lambertian surface, final gathering is
    // replaced by the cache's interpolated irradiance where a record covers the point. nullptr:
    // plain final gathering everywhere (`pm`).
    const IrradianceCache* cache = nullptr;
    int gatherSide = 6;                // a new record gathers gatherSide^2 stratified rays (Eq. 8.18)
    float minR = 1.0f, maxR = 100.0f;  // a record's R is clamped to [minR, maxR] (Eq. 8.18)
    GatherVisitor visitor;             // a later algorithm's terms (empty: pm's own)
};

// pm's settings (plumbing, pm_integrator.cpp), for every algorithm that renders as pm does: the
// estimates' settings in the scene's own length unit (scene.radius), the photon paths per map and
// iteration (as many as the image has pixels, at least 8192), and each map's seed for a render's
// seed (the global and the caustic map trace independent paths).
PmOptions pmOptions(const Scene& scene);
int photonsPerMap(const Image& out);
uint64_t photonSeed(uint64_t seed, MapKind kind);

// Final gathering's ray (the last term of Eq. 8.11): lesson 3's camera walk resumed at sp, leaving
// it in direction wi with throughput `weight`, without Russian roulette; at a specular surface the
// walk samples the BSDF (Transport::Radiance) and goes on; at the first non-specular surface y it
// returns the walk's beta there times radianceEstimate(global, y, y's material, -ray direction,
// opt.globalEstimate) (or the gather visitor's global estimate there, if it has one).
// Black if the ray leaves the scene, a sample fails, the weight becomes black, or it would hit
// more than opt.maxDepth - bounces surfaces (bounces: those the path made before sp). Emission met
// on the way is left out. hitDistance (if not null): the distance from sp to the first surface
// the ray hits, whatever it is (infinity if none).
Color gatherRadiance(const Scene& scene, const SurfacePoint& sp, const Vec3& wi, Color weight, int bounces, Rng& rng,
                     const PhotonMap& global, const PmOptions& opt, float* hitDistance = nullptr);

// Radiance along a camera ray (Eq. 8.11): lesson 3's cameraWalk; emission where the walk sees it
// directly or through specular bounces alone; specular surfaces are followed (the walk goes on);
// at the first non-specular surface x: direct light by next-event estimation (lesson 2's
// sampleDirectLight), caustics from the caustic map (radianceEstimate), and the indirect light by
// final gathering: one BSDF sample from x, followed through specular surfaces to a non-specular
// surface y, where the global map's radianceEstimate towards x is the radiance that arrives
// (gatherRadiance; emission met on the way is left out: next-event estimation and the caustic map
// have it). With opt.cache at a Lambertian x whose point some record covers (interpolateIrradiance
// with the normal on wo's side), the final gather is albedo / pi * the interpolated irradiance
// instead. The walk ends at x. The gather visitor's hooks (opt.visitor), where set, decide whether
// the emission and the light sample count, give the caustic estimate instead of the map's, and
// end the walk at a specular vertex or before x's final gather.
Color LiPhotonMap(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMaps& maps, const PmOptions& opt);

// ---- irradiance caching (irradiance_cache.cpp, Eq. 8.15-8.18) ----

// One of Ward's records: the irradiance final gathering finds at x_i, and how far it may be
// reused.
struct IrradianceRecord {
    Vec3 p;          // x_i
    Vec3 n;          // n_i: unit, on the side of the surface the record was made from
    Color E;         // E_i: the irradiance arriving at x_i through final gathering (Eq. 8.18)
    float R = 0.0f;  // R_i: the harmonic mean distance to the surfaces the gather rays hit (Eq. 8.18)
};

// pm-ic's settings: Ward's error bound a, and the clamp of R_i as fractions of the scene's
// bounding radius (pm_integrator.cpp).
constexpr float kCacheErrorBound = 0.3f, kCacheMinR = 0.03f, kCacheMaxR = 0.5f;

struct IrradianceCache {
    std::vector<IrradianceRecord> records;
    float a = kCacheErrorBound;  // Ward's error bound: a record is used where its weight is > 1 / a (Eq. 8.17)
};

// A record is not used at x if x lies behind it by more than this fraction of R_i (Eq. 8.17).
constexpr float kCacheBehindTolerance = 0.01f;

// Ward's weight of a record at point x with unit normal n (Eq. 8.16):
// w_i = 1 / (|x - x_i| / R_i + sqrt(1 - n . n_i)), +infinity at the record's own point and normal.
float irradianceWeight(const IrradianceRecord& rec, const Vec3& x, const Vec3& n);

// The irradiance at (x, n) from the cache (Eq. 8.17): the w_i-weighted mean of E_i over the
// records with w_i > 1 / cache.a that x is not behind ((x - x_i) . (n + n_i) / 2 >=
// -kCacheBehindTolerance R_i); a record of infinite weight gives its own E_i. Returns false (E
// untouched) when no record qualifies.
bool interpolateIrradiance(const IrradianceCache& cache, const Vec3& x, const Vec3& n, Color& E);

// A new record at sp, made from the side wo points to, at a path vertex after `bounces` bounces
// (Eq. 8.18): gatherSide^2 cosine-weighted directions, one in each cell of a gatherSide x
// gatherSide grid over the unit square (sampleCosineHemisphere around the normal on wo's side),
// each followed by gatherRadiance with weight 1; E = pi / M * sum of the radiances, R = M / sum of
// 1 / hitDistance (a ray that hits nothing adds 0), clamped to [opt.minR, opt.maxR].
IrradianceRecord irradianceRecord(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, int bounces, Rng& rng,
                                  const PhotonMap& global, const PmOptions& opt);

// Fills a cache for one image (irradiance_cache_fill.cpp; plumbing): the first non-specular
// Lambertian surface point seen through each pixel's centre (through specular surfaces on
// lesson 3's walk) is a candidate, coarse to fine (every s-th pixel in both directions, s about a
// quarter of the image's side, then every s/2-th, ..., every pixel); a candidate that no record of
// the earlier levels covers (interpolateIrradiance) gets a new record (irradianceRecord).
// Candidates of one level run in parallel tasks and their records are appended in pixel order,
// so the cache does not depend on the number of threads.
IrradianceCache buildIrradianceCache(const Scene& scene, const PhotonMap& global, const PmOptions& opt, float a,
                                     int width, int height, uint64_t seed, uint32_t iteration, SampleStats& stats);

// ---- progressive photon mapping (progressive.cpp, Eq. 8.13-8.14) ----

// Knaus and Zwicker's alpha (Eq. 8.13): 2/3 balances the squared bias and the variance.
constexpr double kPpmAlpha = 2.0 / 3.0;

// The radius update of Eq. 8.13: the squared radius of pass i + 1 from that of pass i (i >= 1),
// r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1).
double ppmNextRadius2(double r2, int pass, double alpha = kPpmAlpha);

// The squared radius of pass i >= 1 from r_1^2: ppmNextRadius2 applied i - 1 times, in double
// (ppm_integrator.cpp, plumbing).
double ppmRadius2(double r1sq, int pass, double alpha = kPpmAlpha);

// One pass of the `ppm` integrator (ppm_integrator.cpp, plumbing): iteration k is pass k + 1, a
// new global map of photon paths (tracePhotonMap, with `rules` if set) and one camera ray per
// pixel through LiProgressive with the pass's radius (ppmRadius2; the first radius, the photon
// paths per pass and alpha from the scene's render parameters ppmradius, ppmphotons, ppmalpha, or
// their defaults), into out.
void renderPpmPass(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out, SampleStats& stats,
                   const PhotonRules& rules = {});

// One pass's estimate of the radiance along a camera ray (Eq. 8.14): lesson 3's cameraWalk,
// without Russian roulette (its specular bounces are cheap and end at x: a roulette there only
// adds noise); emission where the walk sees it directly or through specular bounces alone;
// specular surfaces followed; at the first non-specular surface x, if v.bounces < maxDepth, the fixed-radius
// density estimate of the map there (radianceEstimate with the box filter, k = 0, radius
// sqrt(r2)) stands for all the light x reflects, direct light included; the walk ends at x.
Color LiProgressive(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMap& map, float r2, int maxDepth);

}  // namespace ps
