// Lesson 12 — the learned field's storage and its schedule (plumbing: read it, nothing to write
// here). The directional tree's total and reset, the spatial tree's root, and GuideField: records
// added cell by cell in parallel, each cell's in the order given (the integrator gives them in task
// order: the field is the same for any number of threads), and the end of a pass (Eq. 12.9,
// 12.11, 12.14):
//
//   1. every side of every cell: its relative error of the pass (lesson 10's 30 %) and the
//      number of records its tree was learnt from;
//   2. the spatial tree cut where the pass recorded more than c sqrt(2^pass) samples
//      (SpatialTree::subdivide), at most as many cells as the memory budget holds;
//   3. per side of every cell: the tree just learnt becomes the sampling tree; its refined copy,
//      emptied, the tree the next pass fills (DirectionalTree::refined); the cosine-weighted
//      incident radiance on that side (Eq. 12.14) for ADRRS;
//   4. while the field is above its budget, every learning tree refined again, coarser (rho
//      doubled, up to the root alone).
#include <algorithm>
#include <cmath>
#include "12-path-guiding/guiding.h"
#include "10-adrrs/adrrs.h"
#include "tasks.h"
#include "warps.h"

namespace ps {

float DirectionalTree::total() const {
    const QuadNode& root = nodes[0];
    return root.energy[0] + root.energy[1] + root.energy[2] + root.energy[3];
}

void DirectionalTree::clear() {
    for (QuadNode& n : nodes) std::fill(n.energy, n.energy + 4, 0.0f);
}

SpatialTree::SpatialTree(const AABB& bounds) : nodes(1), bounds_(bounds) {}

namespace {

// The box of the field: the scene's, a little larger (points on its faces, rounding), never flat.
AABB fieldBox(const AABB& scene) {
    AABB b = scene;
    if (b.empty()) b = AABB{Vec3(-1.0f), Vec3(1.0f)};
    const float pad = 1e-3f * (maxComponent(b.extent()) + 1e-6f);
    b.lo -= Vec3(pad);
    b.hi += Vec3(pad);
    return b;
}

// The six axes of lesson 10's sides (AdjointCache::side): +x, -x, +y, -y, +z, -z.
const Vec3 kSideAxis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

// The integral, over every leaf quadrant under `node` (whose square is [x0, x0 + size]^2), of its
// energy times max(0, cos) towards `axis` (a 3 x 3 midpoint rule over the leaf's square).
double irradianceOf(const DirectionalTree& t, uint32_t node, double x0, double y0, double size, const Vec3& axis) {
    const QuadNode& q = t.nodes[node];
    const double h = 0.5 * size;
    double E = 0.0;
    for (int i = 0; i < 4; ++i) {
        const double qx = x0 + (i & 1) * h, qy = y0 + (i >> 1) * h;
        if (q.child[i] != 0) {
            E += irradianceOf(t, q.child[i], qx, qy, h, axis);
            continue;
        }
        if (!(q.energy[i] > 0.0f)) continue;
        double cosine = 0.0;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                const Vec3 w = sampleUniformSphere(Vec2(float(qx + (a + 0.5) * h / 3), float(qy + (b + 0.5) * h / 3)));
                cosine += std::max(0.0f, dot(w, axis)) / 9.0;
            }
        E += double(q.energy[i]) * cosine;
    }
    return E;
}

size_t cellBytes(const GuideCell& c) {
    size_t b = sizeof(GuideCell);
    for (const GuideSide& s : c.side) b += s.sampling.bytes() + s.learning.bytes();
    return b;
}
size_t learningBytes(const GuideCell& c) {
    size_t b = 0;
    for (const GuideSide& s : c.side) b += s.learning.bytes();
    return b;
}

}  // namespace

GuideField::GuideField(const AABB& sceneBounds, const GuideSettings& settings)
    : settings_(settings), tree_(fieldBox(sceneBounds)), cells_(1) {}

void GuideField::add(const std::vector<RadianceRecord>& records) {
    // Bucketed by cell (in the order given within each), then each cell's records added by one
    // task: in parallel, and the same sums for any number of threads.
    std::vector<uint32_t> first(cells_.size() + 1, 0);
    for (const RadianceRecord& r : records)
        if (valid(r)) ++first[size_t(r.cell) + 1];
    for (size_t c = 0; c < cells_.size(); ++c) first[c + 1] += first[c];
    std::vector<uint32_t> order(first.back());
    std::vector<uint32_t> next(first.begin(), first.end() - 1);
    for (size_t i = 0; i < records.size(); ++i)
        if (valid(records[i])) order[next[size_t(records[i].cell)]++] = uint32_t(i);
    SampleStats stats;
    runTasks(TaskLoop(int(cells_.size()), 0, 0), stats, [&](int c, Rng&, Task&) {
        GuideCell& cell = cells_[size_t(c)];
        for (uint32_t k = first[size_t(c)]; k < first[size_t(c) + 1]; ++k) {
            const RadianceRecord& r = records[order[k]];
            GuideSide& s = cell.side[r.side];
            s.learning.record(r.wi, r.value);
            ++s.samples;
            s.sum += r.value;
            s.sumSq += double(r.value) * r.value;
            ++cell.samples;
        }
    });
    records_ += first.back();
}

bool GuideField::valid(const RadianceRecord& r) const {
    return r.cell >= 0 && size_t(r.cell) < cells_.size() && r.side >= 0 && r.side < 6 && std::isfinite(r.value) &&
           r.value >= 0.0f;
}

void GuideField::endPass(int pass) {
    // 1. What this pass learnt, before the cells are cut (the halves inherit it).
    for (GuideCell& c : cells_)
        for (GuideSide& s : c.side) {
            const double n = s.samples, mean = n > 0 ? s.sum / n : 0.0;
            const double var = n > 1 ? std::max(0.0, (s.sumSq - n * mean * mean) / (n - 1.0)) : 0.0;
            s.error = n > 1 && mean > 0.0 ? float(std::sqrt(var / n) / mean) : kInf;
            s.reliable = s.error <= kMaxRelativeError;
            s.learnt = s.samples;
        }
    // 2. The spatial tree, within the budget: a new cell as large as the largest one will be, with
    //    the two nodes its cut adds to the spatial tree (whose storage may hold twice its nodes).
    size_t perCell = sizeof(GuideCell);
    for (const GuideCell& c : cells_) perCell = std::max(perCell, cellBytes(c) + learningBytes(c));
    perCell += 4 * sizeof(SpatialNode);
    const size_t maxCells = std::max<size_t>(cells_.size(), settings_.budget / perCell);
    const uint32_t threshold = uint32_t(std::lround(settings_.spatialThreshold * std::sqrt(std::ldexp(1.0, pass))));
    tree_.subdivide(cells_, std::max<uint32_t>(threshold, 1), maxCells);
    // 3. Per side of every cell: sample what was learnt, learn into its refined copy.
    for (GuideCell& c : cells_) {
        for (int k = 0; k < 6; ++k) {
            GuideSide& s = c.side[k];
            s.sampling = std::move(s.learning);
            s.learning = s.sampling.refined(settings_.rho, settings_.maxDepth);
            s.learning.clear();
            s.learning.nodes.shrink_to_fit();
            s.irradiance =
                s.learnt > 0 ? float(irradianceOf(s.sampling, 0, 0.0, 0.0, 1.0, kSideAxis[k]) / s.learnt) : 0.0f;
            s.samples = 0;
            s.sum = s.sumSq = 0.0;
        }
        c.samples = 0;
    }
    // 4. Within the budget: coarser learning trees, down to the root alone (rho >= 1 cuts nothing).
    for (float rho = 2.0f * settings_.rho; bytes() > settings_.budget && rho < 2.0f; rho *= 2.0f)
        for (GuideCell& c : cells_)
            for (GuideSide& s : c.side) {
                s.learning = s.sampling.refined(std::min(rho, 1.0f), settings_.maxDepth);
                s.learning.clear();
                s.learning.nodes.shrink_to_fit();
            }
    ++passes_;
}

size_t GuideField::bytes() const {
    size_t b = tree_.bytes();
    for (const GuideCell& c : cells_) b += cellBytes(c);
    return b;
}

}  // namespace ps
