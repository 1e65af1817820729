// Lesson 13's vertex connection and merging (VCM; Georgiev, Krivanek, Davidovic and Slusallek
// 2012): lesson 7's bidirectional path tracer and lesson 8's progressive photon mapping as one
// estimator. Every iteration traces one light subpath per pixel (lesson 7's lightSubpath) and
// stores its vertices in lesson 8's kd-tree; every camera subpath then makes all of lesson 7's
// connections (s, t) with its pixel's light subpath, and at each of its vertices MERGES with the
// light vertices of every light subpath that lie within the radius r: one more sampling
// technique for the same path, whose density is the light vertex's area density times pi r^2
// (Eq. 13.1-13.3), weighted against every connection and every other merge by multiple
// importance sampling (Eq. 13.4-13.11) with the number of light paths N as its sample count. The
// radius shrinks from iteration to iteration (Eq. 13.12), so the estimator is consistent
// (Eq. 13.13). Implemented in solutions/13-vcm/*.cpp (reference) or assignments/13-vcm/*.cpp
// (yours); lessons/13-vcm/README.md derives every formula (Eq. 13.1-13.13).
//
// One vertex type, one walk each way, one kd-tree: the subpaths are lesson 7's (lesson 6's
// PathVertex with lesson 7's pdfFwd, pdfRev and misSum), connections and their weights are
// lesson 7's (connectSubpaths, connectionPdfs, misWeightRecursive), the light vertices' search is
// lesson 8's pointsInRadius. What this lesson adds per vertex, the merging partial sum D_i of
// Eq. 13.8, lives beside the subpath in a MergeSums array (MergeSums[i] belongs to path[i]).
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>
#include "07-bidirectional/bpt.h"
#include "08-photon-mapping/photonmap.h"

namespace ps {

// ---- the radius and the merging density (radius.cpp, Eq. 13.5, 13.12) ----

// The merging radius of iteration i >= 1 (Eq. 13.12): r_1 shrunk by i^((alpha - 1) / 2),
// 0 < alpha <= 1 (alpha = 1: a fixed radius).
double vcmRadius(double r1, int iteration, double alpha);

// eta = n_VM pi r^2 (Eq. 13.5): the factor that turns a connection's density into the density of
// the merge at the same vertex, with the sample counts n_VM = lightPaths (every light subpath of
// the iteration can merge with a camera vertex) and n_VC = 1.
double mergeFactor(double radius, int lightPaths);

// ---- which vertices merge, and the merging partial sums (merge_mis.cpp, Eq. 13.7-13.9) ----

// The per-vertex partial sums of Eq. 13.8 of one subpath: sums[i] = D_i of path[i].
using MergeSums = std::vector<double>;

// mu_i of Eq. 13.7: whether a path's vertex path[i] of a subpath (light or camera) can be the
// vertex a merge happens at, as far as the subpath can tell: not the subpath's first vertex (the
// light's point, the camera), a point on a surface, not specular. (Whether the joined path ends
// there is the caller's business: see mergeTerms.)
bool mergeable(const PathVertex* path, int i);

// D_i for path[i] (Eq. 13.8), once path[i-2].pdfRev is known and sums holds D_0 .. D_{i-1}:
// D_0 = D_1 = 0, D_i = mu_{i-2} (pdfRev_{i-2})^b + (pdfRev_{i-2} / pdfFwd_{i-2})^b D_{i-1}
// (the ratio 0 where pdfFwd is 0); b = 2 for the power heuristic, 1 for the balance heuristic.
// Resizes sums to i + 1 and sets sums[i].
void updateMergeSum(const Subpath& path, size_t i, Heuristic h, MergeSums& sums);

// One subpath's side of a joined path y_0 .. y_{s-1} z_{t-1} .. z_0: its vertices y_0 .. y_{s-1}
// (or z_0 .. z_{t-1}) and their merging sums (not read when count <= 1).
struct SubpathSide {
    const PathVertex* vertices = nullptr;
    const double* mergeSums = nullptr;
    int count = 0;  // s (or t)
};

// The merging part of the denominator of a joined path's weight, M = M^L + M^E of Eq. 13.9, for
// the path y_0 .. y_{s-1} z_{t-1} .. z_0 joined by a connection with reverse densities rev (lesson
// 7's connectionPdfs): the sum over the merges at every vertex the path can merge at, of their
// densities relative to technique (s, t), without the factor eta^b. Pitfall: the last vertex of a
// camera subpath that hit a light (s = 0) is the path's first vertex: no merge there.
double mergeTerms(const SubpathSide& light, const SubpathSide& camera, const ReversePdfs& rev, Heuristic h);

// What the weights of connections and merges depend on besides the path.
struct VcmMis {
    Heuristic heuristic = Heuristic::Power;
    double eta = 0.0;         // Eq. 13.5 (0: no merging)
    bool connections = true;  // the connections are techniques (false: bidirectional photon mapping)
};

// The weight of connection (s, t) among connections AND merges (Eq. 13.10), from its weight wBpt
// among the connections alone (lesson 7's) and M = mergeTerms of its path.
float misWeightConnection(float wBpt, double mergeTermsM, const VcmMis& mis);

// The weight of a merge (Eq. 13.11) of light vertex y_e with camera vertex z_f, read as the
// connection (s = e, t = f + 1) of the merged path y_0 .. y_{e-1} z_f .. z_0 (section 1.5): wBpt
// that connection's lesson 7 weight, rev the merge's junction densities (mergePdfs; rev.cameraEnd
// is the light side's density of the merge vertex), connects whether that connection is itself a
// technique (y_{e-1} not specular), M its mergeTerms. Without connections (mis.connections false)
// merges are weighted against merges only.
float misWeightMerge(float wBpt, bool connects, const ReversePdfs& rev, double mergeTermsM, const VcmMis& mis);

// ---- the light vertices of an iteration, searched by lesson 8's kd-tree (light_vertices.cpp) ----

// Light subpath `path`'s vertex `index` (path = the pixel whose iteration traced it).
struct LightVertexRef {
    uint32_t path = 0, index = 0;
};

struct LightVertices {
    // Every light subpath of the iteration, one after the other in pixel order (lesson 7's
    // lightSubpath), and their merging sums (Eq. 13.8) aligned with them: light subpath i is
    // vertices[starts[i] .. starts[i + 1]).
    std::vector<PathVertex> vertices;
    std::vector<double> sums;
    std::vector<uint32_t> starts;
    // The vertices merges may use (mergeable), in the order of the tree's nodes: refs[k - 1] is
    // node k's.
    std::vector<LightVertexRef> refs;
    KdTree tree;  // lesson 8's kd-tree over their positions (node k: refs[k - 1])
    // Searches and vertices found since the tree was built (for the integrator's report).
    mutable std::atomic<uint64_t> searches{0}, found{0};

    size_t paths() const { return starts.empty() ? 0 : starts.size() - 1; }
    // Light subpath i: its first vertex, its merging sums, its number of vertices.
    const PathVertex* subpath(uint32_t i) const { return vertices.data() + starts[i]; }
    const double* subpathSums(uint32_t i) const { return sums.data() + starts[i]; }
    int length(uint32_t i) const { return int(starts[i + 1] - starts[i]); }
    const PathVertex& vertex(const LightVertexRef& r) const { return vertices[starts[r.path] + r.index]; }
};

// Fills refs with every mergeable vertex of every light subpath and builds the tree over them
// (lesson 8's buildKdTree).
void buildLightVertexTree(LightVertices& lights);

// Every stored light vertex within distance sqrt(r2) of x (lesson 8's pointsInRadius): found is
// cleared first. The order is the tree's.
void lightVerticesWithin(const LightVertices& lights, const Vec3& x, float r2, std::vector<LightVertexRef>& found);

// ---- merging at a camera vertex (merge.cpp, Eq. 13.3, 13.11) ----

enum class VcmMode {
    Vcm,  // every connection of lesson 7 and a merge at every camera vertex, all weighted by MIS
    Bpt,  // connections only: lesson 7's bpt (eta = 0)
    Bpm,  // bidirectional photon mapping: a merge at every camera vertex, weighted against merges
    Ppm,  // progressive photon mapping: a merge at the first non-specular camera vertex, weight 1
};

struct MergeOptions {
    VcmMode mode = VcmMode::Vcm;
    Heuristic heuristic = Heuristic::Power;
    double radius = 0.0;  // r of this iteration
    int lightPaths = 0;   // N, the light subpaths of the iteration (n_VM)
    int maxDepth = 0;     // the scene's: a merged path has at most maxDepth bounces
};

// What a merge gave, for tests and per-technique images (null: nothing recorded).
struct MergeRecorder {
    virtual ~MergeRecorder() = default;
    // light: the light vertex merged with camera vertex f; unweighted: its C*_VM (Eq. 13.3);
    // weight: its MIS weight (Eq. 13.11; 1 for Ppm).
    virtual void add(const LightVertexRef& light, int f, const Color& unweighted, float weight) = 0;
};

// The densities at the junction of the merge of light vertex y_e with camera vertex z_f (y: the
// light subpath, z: the camera subpath; e, f >= 1), in the roles lesson 7's connection (e, f + 1)
// gives them (Eq. 13.10): lightEnd = the camera side's density of y_{e-1}, lightPrev = y_{e-2}'s
// (0 if e < 2), cameraEnd = the light side's density of the merge vertex, cameraPrev = the light
// side's density of z_{f-1}. The merge vertex is z_f seen from the camera side (its material and
// normal), y_e from the light side (its position for the edge to y_{e-1}).
ReversePdfs mergePdfs(const Scene& scene, const PathVertex* y, int e, const PathVertex* z, int f);

// The merges of camera vertex z_f (f >= 1, camera[f] mergeable) with every stored light vertex
// within opt.radius whose merged path has at most opt.maxDepth bounces: the sum of their weighted
// contributions C*_VM w_VM (Eq. 13.3, 13.11). cameraSums: the camera subpath's MergeSums.
Color mergeAtVertex(const Scene& scene, const Subpath& camera, const MergeSums& cameraSums, int f,
                    const LightVertices& lights, const MergeOptions& opt, MergeRecorder* recorder);

// ---- the integrators (plumbing, vcm_integrator.cpp) ----

struct VcmOptions {
    VcmMode mode = VcmMode::Vcm;
    Heuristic heuristic = Heuristic::Power;
    // r_1 = radiusFactor R sqrt(512^2 / N): a fraction of the scene's bounding radius R at 512 x 512
    // pixels (SmallVCM's default there), scaled with the pixels' footprint sqrt(1 / N), N = width x
    // height light paths, so that a merge finds about as many light vertices at any resolution.
    double radiusFactor = 0.003;
    double alpha = 0.75;  // the radius schedule's alpha (Eq. 13.12)
};

// The merging sums of a whole subpath (updateMergeSum for every vertex).
void mergeSums(const Subpath& path, Heuristic h, MergeSums& sums);

// One pixel sample of the camera pass: the camera subpath through raster, then what the mode
// asks: lesson 7's connections with light subpath `pixel` of `lights` (weighted by Eq. 13.10), and
// the merges at the camera vertices with every vertex of `lights`. Without lights (vcm-bpt) the
// light subpath is traced here, after the camera subpath, from the same random numbers as lesson
// 7's bptSample: the sample is then bptSample's, bit for bit.
struct VcmSampleRecorders {
    TechniqueRecorder* connections = nullptr;
    MergeRecorder* merges = nullptr;
};
// `pixel` selects the light subpath of `lights` the connections use (ignored without lights).
Color vcmSample(const Scene& scene, const Vec2& raster, Rng& rng, const VcmOptions& opt, const MergeOptions& merge,
                const LightVertices* lights, uint32_t pixel, const SplatTarget& splat,
                const VcmSampleRecorders& recorders);

// The light pass of an iteration: light subpath i from taskRng(seed ^ kVcmLightSalt, iteration,
// i), with its merging sums, into lights (vertices, sums, starts); the tree is built apart
// (buildLightVertexTree). Bit-identical for any thread count.
constexpr uint64_t kVcmLightSalt = 0x510E527FADE682D1ull;
void traceLightSubpaths(const Scene& scene, int lightPaths, Heuristic h, uint64_t seed, uint32_t iteration,
                        LightVertices& lights, SampleStats& stats);

// r_1 of Eq. 13.12 for these options, a scene and N light paths (VcmOptions::radiusFactor).
double vcmFirstRadius(const VcmOptions& opt, const Scene& scene, int lightPaths);
// What the merges of iteration `iteration` (from 0) use: r_i (Eq. 13.12), N = lightPaths, the
// scene's maxDepth (radius 0 for vcm-bpt).
MergeOptions vcmMergeOptions(const VcmOptions& opt, const Scene& scene, uint32_t iteration, int lightPaths);

// The per-technique images of `pathspace pyramid` (framework/integrator.h, Integrator::techniques):
// row k (path length k, edges) holds the connections (s, t), s + t = k + 1, as lesson 7's pyramid
// (s = 0 only in vcm-bpm and vcm-ppm), then the merges M(e, f) of light vertex y_e with camera
// vertex z_f, e + f = k, e = 1 .. k - 1 (none in vcm-bpt). Each iteration is the integrator's (its
// light pass and radius r_i); the images do not depend on the thread count (vcm_pyramid.cpp).
TechniqueRenderer vcmTechniqueRenderer(const VcmOptions& opt);

// An integrator with these options (the registered ones: vcm, vcm-balance, vcm-bpt, vcm-bpm, vcm-ppm).
std::unique_ptr<Integrator> makeVcmIntegrator(const VcmOptions& opt);

}  // namespace ps
