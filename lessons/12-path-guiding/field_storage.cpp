// Lesson 12 — the learned field's storage and its schedule (plumbing: read it, nothing to write
// here). The directional tree's total and reset, the spatial tree's root, and GuideField: records
// added in the order given (the integrator gives them in task order: the field is the same for any
// number of threads), and the end of a pass (Eq. 12.9, 12.11, 12.14):
//
//   1. every cell's relative error of the pass (lesson 10's 30 %) and the number of records
//      its tree was learnt from;
//   2. the spatial tree cut where the pass recorded more than c sqrt(2^pass) samples
//      (SpatialTree::subdivide), at most as many cells as the memory budget holds;
//   3. per cell: the tree just learnt becomes the sampling tree; its refined copy, emptied, the
//      tree the next pass fills (DirectionalTree::refined); the cosine-weighted incident radiance
//      per side (Eq. 12.14) for ADRRS;
//   4. while the field is above its budget, every learning tree refined again, coarser (rho
//      doubled).
#include <algorithm>
#include <cmath>
#include "12-path-guiding/guiding.h"
#include "10-adrrs/adrrs.h"
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

// Adds, for every leaf quadrant under `node` (whose square is [x0, x0 + size]^2 ...), its energy
// times the mean of max(0, cos) towards each side's axis over its square (a 3 x 3 midpoint rule).
void irradianceOf(const DirectionalTree& t, uint32_t node, double x0, double y0, double size, double out[6]) {
    const QuadNode& q = t.nodes[node];
    const double h = 0.5 * size;
    for (int i = 0; i < 4; ++i) {
        const double qx = x0 + (i & 1) * h, qy = y0 + (i >> 1) * h;
        if (q.child[i] != 0) {
            irradianceOf(t, q.child[i], qx, qy, h, out);
            continue;
        }
        if (!(q.energy[i] > 0.0f)) continue;
        double cosine[6] = {0, 0, 0, 0, 0, 0};
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                const Vec3 w = sampleUniformSphere(Vec2(float(qx + (a + 0.5) * h / 3), float(qy + (b + 0.5) * h / 3)));
                for (int s = 0; s < 6; ++s) cosine[s] += std::max(0.0f, dot(w, kSideAxis[s])) / 9.0;
            }
        for (int s = 0; s < 6; ++s) out[s] += double(q.energy[i]) * cosine[s];
    }
}

size_t cellBytes(const GuideCell& c) { return sizeof(GuideCell) + c.sampling.bytes() + c.learning.bytes(); }

}  // namespace

GuideField::GuideField(const AABB& sceneBounds, const GuideSettings& settings)
    : settings_(settings), tree_(fieldBox(sceneBounds)), cells_(1) {}

void GuideField::add(const std::vector<RadianceRecord>& records) {
    for (const RadianceRecord& r : records) {
        if (r.cell < 0 || size_t(r.cell) >= cells_.size() || !std::isfinite(r.value) || r.value < 0.0f) continue;
        GuideCell& c = cells_[size_t(r.cell)];
        c.learning.record(r.wi, r.value);
        ++c.samples;
        c.sum += r.value;
        c.sumSq += double(r.value) * r.value;
        ++records_;
    }
}

void GuideField::endPass(int pass) {
    // 1. What this pass learnt, before the cells are cut (the halves inherit it).
    for (GuideCell& c : cells_) {
        const double n = c.samples, mean = n > 0 ? c.sum / n : 0.0;
        const double var = n > 1 ? std::max(0.0, (c.sumSq - n * mean * mean) / (n - 1.0)) : 0.0;
        c.reliable = n > 1 && mean > 0.0 && std::sqrt(var / n) / mean <= double(kMaxRelativeError);
        c.learnt = c.samples;
    }
    // 2. The spatial tree, within the budget (each new cell about as large as the average one
    // will be: its two trees at the current average size).
    size_t perCell = sizeof(GuideCell);
    for (const GuideCell& c : cells_) perCell = std::max(perCell, cellBytes(c) + c.learning.bytes());
    const size_t maxCells = std::max<size_t>(cells_.size(), settings_.budget / std::max<size_t>(perCell, 1));
    const uint32_t threshold = uint32_t(std::lround(settings_.spatialThreshold * std::sqrt(std::ldexp(1.0, pass))));
    tree_.subdivide(cells_, std::max<uint32_t>(threshold, 1), maxCells);
    // 3. Per cell: sample what was learnt, learn into its refined copy.
    for (GuideCell& c : cells_) {
        c.sampling = std::move(c.learning);
        c.learning = c.sampling.refined(settings_.rho, settings_.maxDepth);
        c.learning.clear();
        c.learning.nodes.shrink_to_fit();
        double E[6] = {0, 0, 0, 0, 0, 0};
        if (c.learnt > 0) irradianceOf(c.sampling, 0, 0.0, 0.0, 1.0, E);
        for (int s = 0; s < 6; ++s) c.irradiance[s] = c.learnt > 0 ? float(E[s] / c.learnt) : 0.0f;
        c.samples = 0;
        c.sum = c.sumSq = 0.0;
    }
    // 4. Within the budget: coarser learning trees.
    for (float rho = 2.0f * settings_.rho; bytes() > settings_.budget && rho < 1.0f; rho *= 2.0f)
        for (GuideCell& c : cells_) {
            c.learning = c.sampling.refined(rho, settings_.maxDepth);
            c.learning.clear();
            c.learning.nodes.shrink_to_fit();
        }
    ++passes_;
}

size_t GuideField::bytes() const {
    size_t b = tree_.bytes();
    for (const GuideCell& c : cells_) b += cellBytes(c);
    return b;
}

}  // namespace ps
