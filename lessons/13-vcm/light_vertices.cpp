// Lesson 13 — the light vertices of an iteration (plumbing: read it, nothing to write here): one
// light subpath per pixel, traced in the framework's task loop (path i from taskRng(seed ^
// kVcmLightSalt, iteration, i), so the set does not depend on the number of threads), the merging
// sums of each (Eq. 13.8), and lesson 8's kd-tree over the vertices a merge may use.
//
// The tree is lesson 8's PhotonMap: its nodes are Photons, and buildPhotonMap reorders them. A node
// must lead back to its light vertex (the merge needs the vertex's throughput, densities and
// predecessor), so each point is stored with its index into LightVertices::refs in the photon's
// direction field (2 x 16 bits); its power and direction are never read. (When lesson 8's
// kd-tree is made to index any point set, this becomes that.)
#include "13-vcm/vcm.h"
#include "tasks.h"

namespace ps {

void mergeSums(const Subpath& path, Heuristic h, MergeSums& sums) {
    sums.clear();
    for (size_t i = 0; i < path.size(); ++i) updateMergeSum(path, i, h, sums);
}

void buildLightVertexTree(LightVertices& lights) {
    lights.refs.clear();
    std::vector<Photon> points;
    for (size_t p = 0; p < lights.paths.size(); ++p) {
        const Subpath& path = lights.paths[p];
        for (size_t i = 1; i < path.size(); ++i) {
            if (!mergeable(path.data(), int(i))) continue;
            const uint32_t index = uint32_t(lights.refs.size());
            lights.refs.push_back({uint32_t(p), uint32_t(i)});
            Photon ph;
            ph.p = path[i].p();
            ph.dir[0] = uint16_t(index & 0xFFFFu);
            ph.dir[1] = uint16_t(index >> 16);
            points.push_back(ph);
        }
    }
    lights.tree.emitted = int(lights.paths.size());
    buildPhotonMap(std::move(points), lights.tree);
}

void lightVerticesWithin(const LightVertices& lights, const Vec3& x, float r2, std::vector<LightVertexRef>& found) {
    thread_local std::vector<NearPhoton> near;
    found.clear();
    photonsInRadius(lights.tree, x, r2, near);
    for (const NearPhoton& n : near) {
        const Photon& ph = lights.tree.nodes[n.node];
        found.push_back(lights.refs[size_t(ph.dir[0]) | size_t(ph.dir[1]) << 16]);
    }
}

void traceLightSubpaths(const Scene& scene, int lightPaths, Heuristic h, uint64_t seed, uint32_t iteration,
                        LightVertices& lights, SampleStats& stats) {
    lights.paths.resize(size_t(lightPaths));
    lights.sums.resize(size_t(lightPaths));
    runTasks(lightPaths, seed ^ kVcmLightSalt, iteration, nullptr, 0.0f, stats, [&](int i, Rng& rng, Task&) {
        lightSubpath(scene, rng, scene.settings.maxDepth, h, lights.paths[size_t(i)]);
        mergeSums(lights.paths[size_t(i)], h, lights.sums[size_t(i)]);
    });
}

}  // namespace ps
