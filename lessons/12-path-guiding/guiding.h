// Lesson 12's path guiding (Müller, Gross and Novák 2017, "Practical path guiding"): a learned
// field of incident radiance — a binary tree over the scene (the spatial tree) whose every leaf
// holds a quadtree over the sphere of directions (the directional distribution) — learnt from the
// path tracer's own samples, pass after pass, and sampled together with the BSDF (a one-sample
// mixture) inside lesson 3's walk; lesson 10's adjoint-driven roulette and splitting with the
// adjoint taken from the same field; and the same roulette and splitting for particles (lesson
// 5's light tracer, lesson 8's photons), driven by the visual importance a short camera pass
// leaves behind. Implemented in solutions/12-path-guiding/*.cpp (reference) or
// assignments/12-path-guiding/*.cpp (yours); lessons/12-path-guiding/README.md derives every
// formula (Eq. 12.1-12.17).
#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>
#include "03-path-tracing/pathtracer.h"
#include "08-photon-mapping/photonmap.h"
#include "10-adrrs/adrrs.h"

namespace ps {

// ---------------------------------------------------------------------------------------------
// The directional distribution (Eq. 12.5-12.8): a quadtree over the unit square of lesson 1's
// equal-area cylindrical map, s = invertUniformSphere(w) = ((1 - w.z) / 2, phi / 2 pi), whose
// inverse is sampleUniformSphere(s). A node cuts its square into four quadrants, numbered
// i = (s.x >= middle.x) + 2 (s.y >= middle.y); per quadrant it keeps the energy recorded there
// and, if the quadrant is cut further, the index of its node (0: the quadrant is a leaf; node 0
// is the root, which is no one's child). Every quadrant's energy is the sum of its node's four.
struct QuadNode {
    float energy[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    uint32_t child[4] = {0, 0, 0, 0};
};

// A quadrant is cut (refined) while it holds more than this fraction of the total energy (Müller
// et al.'s rho), down to kMaxQuadDepth levels (the root's quadrants are at depth 1).
constexpr float kRefineFraction = 0.01f;
constexpr int kMaxQuadDepth = 16;

class DirectionalTree {
public:
    // The root alone: four leaf quadrants without energy.
    DirectionalTree() : nodes(1) {}

    // The density of direction w per unit solid angle (Eq. 12.6): the density per unit area of the
    // square at s (the quadrant's share of its node's energy, times 4, at every level down to the
    // leaf), converted to solid angle by the map's constant Jacobian (Eq. 12.5). A tree whose total
    // energy is 0 is uniform over the sphere. w unit.
    float pdf(const Vec3& w) const;
    // Draws a direction with that density (Eq. 12.7): down from the root, a quadrant chosen with
    // probability proportional to its energy, the uniform numbers u rescaled to the chosen part at
    // every level and reused; in the leaf's square, the point its rescaled numbers give, mapped to
    // the sphere. u in [0, 1)^2. A tree whose total is 0: uniform over the sphere.
    Vec3 sample(const Vec2& u) const;
    // Adds value (>= 0) to the energy of every quadrant that contains w's point of the square, from
    // the root down to its leaf (Eq. 12.8).
    void record(const Vec3& w, float value);
    // The tree refined after a pass (Eq. 12.9): the same total, every quadrant whose energy is
    // above rho times the total cut into four (a leaf's energy shared equally by its four new
    // quadrants, which are looked at again), every quadrant at or below it a leaf (what was under
    // it merged into it), no quadrant deeper than maxDepth. A tree with total 0 comes out as it is.
    DirectionalTree refined(float rho = kRefineFraction, int maxDepth = kMaxQuadDepth) const;

    // Plumbing (field_storage.cpp). The total energy: the sum of the root's four quadrants.
    float total() const;
    // Every quadrant's energy set to 0, the structure kept (the tree a new pass fills).
    void clear();
    // Bytes of its nodes.
    size_t bytes() const { return nodes.capacity() * sizeof(QuadNode); }

    std::vector<QuadNode> nodes;
};

// ---------------------------------------------------------------------------------------------
// The spatial tree (Eq. 12.10, 12.11): a binary tree over the scene's box; a node is cut in half
// across the middle of its box along axis depth mod 3 (x, y, z, x, ...), so that every leaf's box
// follows from the path down to it. A leaf holds one cell of the field.
struct SpatialNode {
    uint32_t child[2] = {0, 0};  // the two halves (lower, upper coordinate); 0 for a leaf
    uint32_t cell = 0;           // a leaf's cell (index into GuideField::cells)
    uint8_t axis = 0;            // the axis this node cuts (depth mod 3)
    bool isLeaf() const { return child[0] == 0; }
};

// What a cell of the field holds, per side of a surface (lesson 10's six sides,
// AdjointCache::side): the floor and the wall beside it, or the two faces of a wall, see different
// hemispheres and are kept apart. Per side: the directional distribution learnt in the pass before
// (`sampling`: the guide samples it), the one this pass fills (`learning`), and what was recorded
// into `learning` (plumbing; the adjoint and its reliability read it).
struct GuideSide {
    DirectionalTree sampling, learning;
    uint32_t samples = 0;           // records added to `learning` in this pass
    double sum = 0.0, sumSq = 0.0;  // of their values (for the relative error, lesson 10's 30 %)
    uint32_t learnt = 0;            // records `sampling` was learnt from (its energies over this
                                    // are integrals of the incident radiance, Eq. 12.13)
    // The adjoint taken from `sampling` (Eq. 12.14): the cosine-weighted incident radiance on this
    // side, and whether the pass it was learnt in gave it a relative error within
    // kMaxRelativeError (lesson 10).
    float irradiance = 0.0f;
    bool reliable = false;
    float error = kInf;  // the relative standard error of that pass's mean record (reliable: <= 30 %)
};
struct GuideCell {
    GuideSide side[6];
    uint32_t samples = 0;  // records of all its sides in this pass (the spatial tree's cut, Eq. 12.11)
};

class SpatialTree {
public:
    SpatialTree() = default;
    // One leaf (one cell) over `bounds`.
    explicit SpatialTree(const AABB& bounds);

    // The cell of the leaf whose box contains p (Eq. 12.10): down from the root, the upper half
    // where p's coordinate along the node's axis is at or above the middle of the node's box, else
    // the lower half. A point outside the root's box goes where its coordinates say (the first or
    // last leaf along each axis).
    uint32_t cellOf(const Vec3& p) const;
    // Cuts every leaf whose cell received more than `threshold` records this pass (Eq. 12.11): its
    // two halves along the node's axis are new leaves, the lower keeping the cell's index, the
    // upper a new cell appended to `cells`, each a copy of the cell (its trees and statistics) with
    // half its records (rounded down); a half that still has more than `threshold` is cut again.
    // Stops early, leaving leaves uncut, once `cells` has maxCells cells.
    void subdivide(std::vector<GuideCell>& cells, uint32_t threshold, size_t maxCells);

    const AABB& bounds() const { return bounds_; }
    size_t bytes() const { return nodes.capacity() * sizeof(SpatialNode); }
    std::vector<SpatialNode> nodes;  // nodes[0] is the root

private:
    AABB bounds_;
};

// ---------------------------------------------------------------------------------------------
// Learning (Eq. 12.12, 12.13): every direction a camera path samples at a non-delta vertex gives
// one record of the radiance that arrived along it, to the cell of the vertex it left.

// One vertex x_j of a camera sample — a path, or with splitting a tree of paths — in the order the
// walk reached them (depth first), with the direction sample that led to it. A sample that the
// roulette ended before it reached a vertex is an entry too, with nothing added.
struct GuideVertex {
    int from = -1;      // the vertex whose sample led here (its index in the list); -1 for x_0
    int cell = -1;      // the field's cell of that vertex, which gets the record; -1: no record
                        // (x_0, a delta bounce)
    int side = 0;       // the side of the surface there (AdjointCache::side), which gets it
    Vec3 wi;            // the sampled direction (unit, world space), from x_from towards x_j
    float pdf = 0.0f;   // its density per unit solid angle (the mixture's, Eq. 12.3)
    Color throughput;   // the throughput just after the sample: beta_from f |cos| / pdf, before any
                        // roulette (Eq. 12.12's t)
    Color added;        // what x_j added to the estimate (lesson 3's misEmission + misLightSample)
    Color emitted;      // of that, the MIS-weighted emission found at x_j (misEmission)
    Color emittedFull;  // the emission found at x_j without the MIS weight, times beta_j
};
// One record: the cell, the direction and the value the directional tree adds (Eq. 12.13).
struct RadianceRecord {
    int cell = -1, side = 0;
    Vec3 wi;
    float value = 0.0f;
};
// The records of one camera sample (Eq. 12.12, 12.13), for every vertex j with a cell, in order:
// the radiance that arrived along wi — what x_j and every vertex after it on its branch (the
// vertices whose chain of `from` leads back to j) added, with x_j's MIS-weighted emission replaced
// by its full emission —, divided channel by channel by the throughput (0 in a channel where it is
// 0), as one number (the mean of the channels), divided by the pdf; to the vertex's cell and side.
// Appended to `out`.
void radianceRecords(const std::vector<GuideVertex>& path, std::vector<RadianceRecord>& out);

// ---------------------------------------------------------------------------------------------
// The learned field, as the integrators use it (plumbing: field_storage.cpp): the spatial tree,
// its cells, and the schedule of passes.
struct GuideSettings {
    // A leaf is cut when it received more than kSpatialThreshold * sqrt(2^pass) records in a pass
    // of 2^pass samples per pixel (Müller et al.'s c sqrt(2^k), Eq. 12.11).
    uint32_t spatialThreshold = 4000;
    // The most memory the field may take (both trees of every cell and the spatial tree), in
    // bytes: no cut and no refinement that would take it above (--guide-budget, in MB).
    size_t budget = size_t(64) << 20;
    float rho = kRefineFraction;
    // A side guides only once its sampling tree was learnt from this many records: below it the
    // guide is a fit to a few heavy-tailed radiance estimates and guiding by it loses to BSDF
    // sampling (measured on the door: 2x pt's relMSE at 64 spp without the gate, pt's with it;
    // lessons/12-path-guiding/diagnosis.md).
    uint32_t minRecords = 5000;
    int maxDepth = kMaxQuadDepth;
};

class GuideField {
public:
    GuideField() = default;
    GuideField(const AABB& sceneBounds, const GuideSettings& settings);
    // A field made by hand (tests): this spatial tree and these cells.
    GuideField(const SpatialTree& tree, std::vector<GuideCell> cells) : tree_(tree), cells_(std::move(cells)) {}

    // The cell of p, and what it learnt in the pass before.
    uint32_t cellOf(const Vec3& p) const { return tree_.cellOf(p); }
    const GuideCell& cell(uint32_t c) const { return cells_[c]; }
    size_t cells() const { return cells_.size(); }
    // Whether a side of a cell guides: its sampling tree has energy and was learnt from at least
    // settings.minRecords records (a tree fitted to fewer is mostly noise, README section 5).
    bool canGuide(uint32_t c, int side) const {
        const GuideSide& s = cells_[c].side[side];
        return s.learnt >= settings_.minRecords && s.sampling.total() > 0.0f;
    }

    // Adds one pass's records, in the order given (the same for any number of threads).
    void add(const std::vector<RadianceRecord>& records);
    // Ends a pass of 2^pass samples per pixel (Eq. 12.11, 12.9): cuts the spatial tree where the
    // pass recorded many samples, makes every cell's learnt tree its sampling tree and a refined
    // copy without energy its new learning tree, and computes the cells' adjoint (Eq. 12.14),
    // within the memory budget.
    void endPass(int pass);

    const SpatialTree& spatialTree() const { return tree_; }
    // Bytes of the whole field (both trees of every cell, the cells and the spatial tree).
    size_t bytes() const;
    int passes() const { return passes_; }
    uint64_t records() const { return records_; }

private:
    bool valid(const RadianceRecord& r) const;
    GuideSettings settings_;
    SpatialTree tree_;
    std::vector<GuideCell> cells_;
    int passes_ = 0;
    uint64_t records_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Guided sampling (Eq. 12.3, 12.4): a one-sample mixture of the guide (a cell's sampling tree)
// and the BSDF, with the probability alpha of taking the guide.
constexpr float kGuideFraction = 0.5f;  // alpha where a cell can guide (Müller et al.'s choice)

// The mixture's density of wi at a non-delta vertex with normal n, wo towards the previous vertex
// (Eq. 12.3): alpha times the guide's density plus (1 - alpha) times pdfBSDF, both per unit solid
// angle.
float guidedPdf(const Material& m, const Vec3& n, const Vec3& wo, const DirectionalTree& guide, float alpha,
                const Vec3& wi);
// One direction from the mixture (Eq. 12.3, 12.4), camera side (Transport::Radiance). At a delta
// material: lesson 3's sampleBSDF(m, n, wo, u, uLobe, Transport::Radiance, s) with u = rng.uniform2()
// drawn before uLobe = rng.uniform(), and nothing else (a delta lobe is never guided). Otherwise: one rng.uniform() chooses — below
// alpha the guide (guide.sample(rng.uniform2())), else the BSDF (sampleBSDF as above, which may
// fail) —; then s.pdf = guidedPdf(wi), s.weight = f(wo, wi) |cos theta_i| / s.pdf, s.delta false.
// False where no direction came out or f is black there (a guide direction below the surface).
bool sampleGuided(const Material& m, const Vec3& n, const Vec3& wo, const DirectionalTree& guide, float alpha, Rng& rng,
                  BSDFSample& s);

// ---------------------------------------------------------------------------------------------
// Roulette and splitting from an adjoint (Eq. 12.15 with lesson 10's window, Eq. 10.2, 10.5-10.7).

// What a rule decided at a vertex: decided = false where it cannot (the walk's own roulette then
// plays, as in the algorithm without the rule); else the expected number of continuations q.
struct Decision {
    bool decided = false;
    float q = 1.0f;
};
// q for a path (or particle) of throughput beta at a vertex whose adjoint (what it will still
// bring per unit of throughput, RGB) is `adjoint`, where the ideal path brings `measurement`
// (Eq. 12.15): lesson 10's weight nu = sum_c beta_c adjoint_c / sum_c adjoint_c (the mean of beta's
// channels for a black adjoint), the adjoint as one number (the mean of its channels), and
// expectedContinuations(nu, weightWindow(measurement, that number)).
float windowContinuations(const Color& beta, const Color& adjoint, float measurement);

// The adjoint the field gives at a non-delta vertex with material m and normal n, seen from wo
// (Eq. 12.14): the material's albedo / pi times the irradiance of the cell's side that wo sees
// (lesson 10's AdjointCache::side(n, wo)).
Color fieldAdjoint(const GuideCell& cell, const Material& m, const Vec3& n, const Vec3& wo);
// The pixel estimate from the field (Eq. 10.9 on the field): the mean of the channels of
// fieldAdjoint at the camera ray's first vertex x0; -1 where the field cannot say (a miss, a
// delta material, a side of a cell that is not reliable).
float fieldPixelEstimate(const GuideField& field, const Scene& scene, const WalkVertex& x0);
// The decision at camera vertex v (Eq. 12.14, 12.15): none where pixelEstimate < 0, at a miss, a
// delta material or where the side of v's cell that v.wo sees is not reliable; else windowContinuations(v.beta, fieldAdjoint,
// pixelEstimate).
Decision fieldDecision(const GuideField& field, const Scene& scene, const WalkVertex& v, float pixelEstimate);

// ---------------------------------------------------------------------------------------------
// Particles (Eq. 12.16, 12.17): visual importance from a short camera pass.

// One vertex of the camera pass as the importance cache sees it.
struct ImportanceVertex {
    bool store = false;  // a hit on a non-delta material: an importon is left there
    Vec3 p, n, wo;       // the point, its normal and the direction back along the camera path
    Color beta;          // the camera path's throughput beta_k there
};
// The importons of one camera path (Eq. 12.16): one lesson-8 photon at every vertex that stores
// one, at p, its "power" the throughput times pixels / paths (P pixels, M camera paths in the
// whole pass), its direction (setWLight) wo. Appended to `out`.
void appendImportons(const std::vector<ImportanceVertex>& path, int pixels, int paths, std::vector<Photon>& out);
// The decision at a particle's vertex y (Eq. 12.17): none at a delta material or where the
// importance cache's entry for y (cache.entry(y.sp.p, y.sp.n, y.wo): the side the particle
// arrived on) is not reliable; else windowContinuations(y.beta, W~, imageTotal) with W~ the
// material's albedo times the entry's estimate (the importance reflected by a white Lambertian
// surface there).
Decision particleDecision(const AdjointCache& importance, const Scene& scene, const WalkVertex& y, float imageTotal);

// ---------------------------------------------------------------------------------------------
// The integrators (plumbing). "pt-guided" and "pt-guided-adrrs" (guided_integrator.cpp): lesson
// 3's path tracer on the guided mixture, learning its field pass after pass; with ADRRS on the
// field as the walk's continuation rule.
//
// The schedule's last pass (Müller et al. 2017, section 5.3): a render of T seconds stops
// learning once the time left is below kLastPassRatio times the pass just ended (the next pass
// would take about twice it and the one after four times: the one after could not finish), and
// samples that field to the end, at least half of the render.
constexpr double kLastPassRatio = 6.0;
class GuidedPathTracer : public Integrator {
public:
    // adrrs: "pt-guided-adrrs"; budget: the field's memory cap in bytes (--guide-budget), 0: the
    // default (GuideSettings).
    explicit GuidedPathTracer(bool adrrs = false, size_t budget = 0) : adrrs_(adrrs), budget_(budget) {}
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override;
    std::vector<std::string> report() const override;
    const GuideField& field() const { return field_; }
    uint64_t decisions() const { return decisions_; }

private:
    bool adrrs_;
    size_t budget_;
    GuideField field_;
    bool learning_ = true;    // whether this pass records (false from the last pass on)
    int lastPass_ = -1;       // the last pass, once known
    uint32_t lastFrom_ = 0;   // its first iteration
    double passStart_ = 0.0;  // secondsLeft() as the current pass began
    uint64_t decisions_ = 0, roulette_ = 0, splits_ = 0;
};

// "lt-adrrs" and "ppm-adrrs" (particle_integrator.cpp): the camera pass (Eq. 12.16, 12.17) and the
// rule it gives the particles' walks.
struct ImportancePass {
    AdjointCache cache;       // the importance reflected by a white Lambertian surface, per entry
    float imageTotal = 0.0f;  // T (Eq. 12.17), the mean of its channels
    size_t importons = 0;
    int paths = 0;
};
// `paths` camera paths of lesson 3's pt (path i through pixel i mod pixels), their importons, and
// lesson 8's k-nearest density estimate at up to 2^15 of them into lesson 10's cache (the same for
// any number of threads).
ImportancePass importancePass(const Scene& scene, int paths, uint64_t seed, SampleStats& stats);
// What the particles' rule decided, summed over the threads.
struct ParticleCounts {
    std::atomic<uint64_t> decisions{0}, roulette{0}, splits{0};
    void reset() { decisions = roulette = splits = 0; }
};
// particleDecision as the continuation rule of one particle's walk (lesson 3's Eq. 3.10): where it
// decides, lesson 10's continuations with the walk's own roulette off after them; where it does
// not, one continuation and the walk's own roulette. At most kMaxPathsPerCameraRay paths per
// particle, as lesson 10 allows a camera ray.
ContinuationRule particleRule(const Scene& scene, const ImportancePass& pass, ParticleCounts& counts);

}  // namespace ps
