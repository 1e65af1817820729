// Lesson 8 — the photon's storage and the photon pass (plumbing: read it, nothing to write
// here): the octahedral direction encoding of Photon, the photon map on your kd-tree (the tree of
// the photons' positions, the photons in its node order), the filters' names, and tracePhotonMap,
// which traces a map's photon paths in the framework's parallel task loop (framework/tasks.h):
// path i draws from taskRng(seed, iteration, i), each task keeps its photons in its own list, and
// the lists are joined in task order, so the map does not depend on the number of threads.
#include <algorithm>
#include <cmath>
#include <utility>
#include "08-photon-mapping/photonmap.h"
#include "tasks.h"

namespace ps {

namespace {
float signNotZero(float v) { return v >= 0.0f ? 1.0f : -1.0f; }
uint16_t quantize(float v) {  // [-1, 1] -> [0, 65535]
    return static_cast<uint16_t>(std::lround((std::clamp(v, -1.0f, 1.0f) * 0.5f + 0.5f) * 65535.0f));
}
float dequantize(uint16_t q) { return float(q) / 65535.0f * 2.0f - 1.0f; }
}  // namespace

// Octahedral encoding: w projected onto the octahedron |x| + |y| + |z| = 1, the lower half folded
// over the upper one, the two coordinates in 16 bits each.
void Photon::setWLight(const Vec3& w) {
    const float l1 = std::abs(w.x) + std::abs(w.y) + std::abs(w.z);
    float x = l1 > 0.0f ? w.x / l1 : 0.0f, y = l1 > 0.0f ? w.y / l1 : 0.0f;
    if (w.z < 0.0f) {
        const float fx = (1.0f - std::abs(y)) * signNotZero(x), fy = (1.0f - std::abs(x)) * signNotZero(y);
        x = fx;
        y = fy;
    }
    dir[0] = quantize(x);
    dir[1] = quantize(y);
}

Vec3 Photon::wLight() const {
    float x = dequantize(dir[0]), y = dequantize(dir[1]);
    const float z = 1.0f - std::abs(x) - std::abs(y);
    if (z < 0.0f) {
        const float fx = (1.0f - std::abs(y)) * signNotZero(x), fy = (1.0f - std::abs(x)) * signNotZero(y);
        x = fx;
        y = fy;
    }
    return glm::normalize(Vec3(x, y, z));
}

static_assert(sizeof(Photon) <= 32, "a photon must fit in 32 bytes");

namespace {

// The cells of the grid spatialOrder sorts by: 2^kOrderBits per axis.
constexpr int kOrderBits = 5;

// The Morton code of a cell (x, y, z < 2^kOrderBits): their bits interleaved, x's highest first.
uint32_t mortonCode(uint32_t x, uint32_t y, uint32_t z) {
    uint32_t code = 0;
    for (int b = kOrderBits - 1; b >= 0; --b)
        code = (code << 3) | ((x >> b) & 1u) << 2 | ((y >> b) & 1u) << 1 | ((z >> b) & 1u);
    return code;
}

// The photons' indices in a spatial order: by the Morton code of their cell in a grid of
// 2^kOrderBits cells per axis over their bounding box, in their own order within a cell (a
// counting sort: O(n)). Neighbours in space become neighbours in the list, so the kd-tree build's
// partitions of the upper levels meet their points mostly sorted (their comparisons predictable:
// on SmallVCM's scenes the build takes about a quarter less time) and read them in order.
std::vector<uint32_t> spatialOrder(const std::vector<Photon>& photons) {
    std::vector<uint32_t> order(photons.size());
    if (photons.empty()) return order;
    Vec3 lo = photons[0].p, hi = lo;
    for (const Photon& ph : photons) {
        lo = glm::min(lo, ph.p);
        hi = glm::max(hi, ph.p);
    }
    const float cells = float(1 << kOrderBits);
    const Vec3 extent = hi - lo;
    const Vec3 scale(extent.x > 0.0f ? cells / extent.x : 0.0f, extent.y > 0.0f ? cells / extent.y : 0.0f,
                     extent.z > 0.0f ? cells / extent.z : 0.0f);
    // A coordinate's cell: 0 below the first cell's top and for NaN (a position that is not
    // finite makes no error here: the order only has to be some order), the last cell at the top.
    const auto cell = [cells](float c) { return !(c >= 1.0f) ? 0u : uint32_t(std::min(c, cells - 1.0f)); };
    std::vector<uint32_t> code(photons.size());
    std::vector<uint32_t> start(size_t(1) << (3 * kOrderBits), 0u);
    for (size_t i = 0; i < photons.size(); ++i) {
        const Vec3 c = (photons[i].p - lo) * scale;  // in [0, cells]; the top edge goes to the last cell
        code[i] = mortonCode(cell(c.x), cell(c.y), cell(c.z));
        ++start[code[i]];
    }
    uint32_t sum = 0;
    for (uint32_t& s : start) sum += std::exchange(s, sum);
    for (size_t i = 0; i < photons.size(); ++i) order[start[code[i]]++] = uint32_t(i);
    return order;
}

}  // namespace

void buildPhotonMap(std::vector<Photon> photons, PhotonMap& map) {
    // The tree is handed the points in a spatial order (spatialOrder); item[i] then indexes that order.
    const std::vector<uint32_t> order = spatialOrder(photons);
    std::vector<Vec3> points(photons.size());
    for (size_t i = 0; i < photons.size(); ++i) points[i] = photons[order[i]].p;
    buildKdTree(points, map.tree);
    map.nodes.assign(map.tree.size() + (map.tree.size() > 0 ? 1 : 0), Photon());
    for (size_t i = 1; i <= map.tree.size(); ++i) map.nodes[i] = photons[order[map.tree.item[i]]];
}

int nearestPhotons(const PhotonMap& map, const Vec3& x, int k, float maxD2, std::vector<NearPhoton>& found) {
    return nearestPoints(map.tree, x, k, maxD2, found);
}

int photonsInRadius(const PhotonMap& map, const Vec3& x, float r2, std::vector<NearPhoton>& found) {
    found.clear();
    return pointsInRadius(map.tree, x, r2, [&](uint32_t node, float d2, float&) { found.push_back({node, d2}); });
}

const char* filterName(Filter f) {
    switch (f) {
    case Filter::Box: return "box";
    case Filter::Cone: return "cone";
    case Filter::Gaussian: return "Gaussian";
    }
    return "?";
}

std::vector<PhotonMap> tracePhotonPopulations(const Scene& scene, MapKind kind, int emitted, int maxDepth,
                                              uint64_t seed, uint32_t iteration, SampleStats& stats,
                                              const std::function<PhotonVisitor()>& newVisitor,
                                              const PhotonRules& rules) {
    std::vector<PhotonMap> maps(1);
    maps[0].emitted = emitted;
    if (emitted <= 0) return maps;
    std::vector<std::vector<Photon>> perTask(size_t(taskCount(emitted)));
    runTasks(TaskLoop(emitted, seed, iteration), stats, [&](int, Rng& rng, Task& task) {
        tracePhoton(scene, rng, maxDepth, kind, emitted, perTask[task.index], newVisitor ? newVisitor() : nullptr,
                    rules ? rules() : ContinuationRule());
    });
    // The photons of each population in path order. A photon whose power is NaN or Inf is counted
    // (as a sample would be) and not stored.
    std::vector<std::vector<Photon>> populations(1);
    size_t total = 0;
    for (const auto& list : perTask) total += list.size();
    populations[0].reserve(total);  // most algorithms have one population: no copy as it grows
    for (const auto& list : perTask)
        for (const Photon& ph : list) {
            if (!isFinite(ph.power)) {
                checkSample(ph.power, stats);
                continue;
            }
            if (ph.population >= populations.size()) populations.resize(size_t(ph.population) + 1);
            populations[ph.population].push_back(ph);
        }
    maps.resize(populations.size());
    for (size_t p = 0; p < populations.size(); ++p) {
        maps[p].emitted = emitted;
        buildPhotonMap(std::move(populations[p]), maps[p]);
    }
    return maps;
}

PhotonMap tracePhotonMap(const Scene& scene, MapKind kind, int emitted, int maxDepth, uint64_t seed, uint32_t iteration,
                         SampleStats& stats, const PhotonRules& rules) {
    return std::move(tracePhotonPopulations(scene, kind, emitted, maxDepth, seed, iteration, stats, nullptr, rules)[0]);
}

}  // namespace ps
