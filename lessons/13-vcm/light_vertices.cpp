// Lesson 13 — the light vertices of an iteration (plumbing: read it, nothing to write here): one
// light subpath per pixel, traced in the framework's task loop (path i from taskRng(seed ^
// kVcmLightSalt, iteration, i), so the set does not depend on the number of threads), with the
// merging sums of each (Eq. 13.8), kept one after the other in one array; and lesson 8's kd-tree
// over the vertices a merge may use.
//
// The tree is lesson 8's kd-tree over any set of points (KdTree, buildKdTree, pointsInRadius) built
// over the positions of the vertices a merge may use; afterwards that list is put into the tree's
// node order (node k's vertex is refs[k - 1]), so that a search reads the refs it finds in the
// order the tree stores them.
#include "13-vcm/vcm.h"
#include "tasks.h"

namespace ps {

// lightVerticesWithin's reads go here (never used; not static, so that the compiler keeps them).
extern thread_local float lightVertexTouch;
thread_local float lightVertexTouch = 0.0f;

void mergeSums(const Subpath& path, Heuristic h, MergeSums& sums) {
    sums.clear();
    for (size_t i = 0; i < path.size(); ++i) updateMergeSum(path, i, h, sums);
}

void buildLightVertexTree(LightVertices& lights) {
    std::vector<LightVertexRef> refs;
    std::vector<Vec3> points;
    for (uint32_t p = 0; p < uint32_t(lights.paths()); ++p) {
        const PathVertex* path = lights.subpath(p);
        for (int i = 1; i < lights.length(p); ++i) {
            if (!mergeable(path, i)) continue;
            refs.push_back({p, uint32_t(i)});
            points.push_back(path[i].p());
        }
    }
    buildKdTree(points, lights.tree);
    lights.refs.resize(refs.size());
    for (size_t k = 1; k <= lights.tree.size(); ++k) lights.refs[k - 1] = refs[lights.tree.item[k]];
    lights.searches = 0;
    lights.found = 0;
}

void lightVerticesWithin(const LightVertices& lights, const Vec3& x, float r2, std::vector<LightVertexRef>& found) {
    found.clear();
    pointsInRadius(lights.tree, x, r2, [&](uint32_t node, float, float&) { found.push_back(lights.refs[node - 1]); });
    lights.searches.fetch_add(1, std::memory_order_relaxed);
    lights.found.fetch_add(found.size(), std::memory_order_relaxed);
    // One number of each vertex found (and of its predecessor) is read here, before the merges
    // use them: the loads of this short loop overlap, so the vertices' memory arrives together
    // instead of one cache miss at a time inside the merges (measured: a fifth of vcm's time at
    // 512 x 512 pixels, where the light vertices fill 100 MB).
    float touch = 0.0f;
    for (const LightVertexRef& r : found) {
        const PathVertex* y = lights.subpath(r.path) + r.index;
        touch += y[-1].pdfFwd + y[0].pdfFwd;
    }
    lightVertexTouch = touch;
}

void traceLightSubpaths(const Scene& scene, int lightPaths, Heuristic h, uint64_t seed, uint32_t iteration,
                        LightVertices& lights, SampleStats& stats) {
    // Each task keeps its subpaths in its own lists, joined in task order afterwards.
    struct TaskPaths {
        std::vector<PathVertex> vertices;
        std::vector<double> sums;
    };
    std::vector<TaskPaths> perTask(size_t(taskCount(lightPaths)));
    std::vector<uint32_t> lengths(static_cast<size_t>(lightPaths));
    runTasks(TaskLoop(lightPaths, seed ^ kVcmLightSalt, iteration), stats, [&](int i, Rng& rng, Task& task) {
        thread_local Subpath path;
        thread_local MergeSums sums;
        lightSubpath(scene, rng, scene.settings.maxDepth, h, path);
        mergeSums(path, h, sums);
        TaskPaths& out = perTask[task.index];
        out.vertices.insert(out.vertices.end(), path.begin(), path.end());
        out.sums.insert(out.sums.end(), sums.begin(), sums.end());
        lengths[size_t(i)] = uint32_t(path.size());
    });
    lights.starts.assign(size_t(lightPaths) + 1, 0);
    for (size_t i = 0; i < lengths.size(); ++i) lights.starts[i + 1] = lights.starts[i] + lengths[i];
    lights.vertices.clear();
    lights.sums.clear();
    lights.vertices.reserve(lights.starts.back());
    lights.sums.reserve(lights.starts.back());
    for (const TaskPaths& t : perTask) {
        lights.vertices.insert(lights.vertices.end(), t.vertices.begin(), t.vertices.end());
        lights.sums.insert(lights.sums.end(), t.sums.begin(), t.sums.end());
    }
}

}  // namespace ps
