// Lesson 11 — plumbing: `lt --paths EXPR`, light tracing restricted to the paths an expression
// matches (path_filter.h). Each light path is lesson 7's light subpath y_0 .. y_m (lesson 5's
// light walk, storing its vertices, surviving by the material: Eq. 7.1a, where lt's own walk
// survives by Eq. 3.5, so `lt --paths 'L.*E'` is lt in expectation, not bit for bit), read forward from L; vertex y_{s-1} is joined to the camera
// by lesson 7's connectCamera (lesson 5's connection and estimate, Eq. 5.3-5.5) if the path
// L y_1 .. y_{s-1} E matches. Where no path through y_{s-1} can match any more (Eq. 11.6) the
// later vertices are not joined, and when the expression bounds the number of bounces (`LDE`:
// one) the subpath is traced no further: the walk's first vertices and their random numbers are
// the same either way, and every light path has its own, so the image does not change.
//
// A thin-lens camera (lesson 11, thinlens.h): as lt (lesson 5's traceLightPath), each light path
// draws one point z on the lens before its walk, and every vertex joins that z (connectCamera
// divides by its density, camera.pdfPoint()); the string's E is z. A pinhole draws no number.
#include <atomic>
#include "11-classics/path_filter.h"
#include "tasks.h"

namespace ps {

namespace {

struct FilteredLightTracer : Integrator {
    explicit FilteredLightTracer(const PathExpression& e) : paths(e) {}
    PathExpression paths;

    // The bounces a light subpath needs: the scene's maximum, or fewer if the expression bounds
    // the number of vertices between L and E (when pruning).
    int depth(const Scene& scene) const {
        const int longest = paths.longestInterior(sceneTypes(scene));
        if (!scene.settings.prune || longest == PathExpression::kUnbounded) return scene.settings.maxDepth;
        return std::min(scene.settings.maxDepth, longest);
    }

    std::vector<std::string> leftOut(const Scene& scene) const override {
        std::vector<std::string> lines = pathFilterLeftOut(
            paths, scene,
            "a light path is joined to the camera up to its last vertex from which a path can still match (Eq. 11.6)");
        if (scene.settings.prune && sceneCanMatch(paths, scene) && depth(scene) < scene.settings.maxDepth)
            lines.push_back("light paths beyond " + std::to_string(depth(scene)) +
                            " bounces: no longer path matches '" + paths.text() + "' on this scene");
        return lines;
    }

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        if (scene.settings.prune && !sceneCanMatch(paths, scene)) return;
        const int maxDepth = depth(scene);
        const bool prune = scene.settings.prune;
        renderLightPathTasks(seed, iteration, out, stats, [&](int, Rng& rng, Task& task) {
            thread_local Subpath light;
            const PathVertex z0 = cameraVertex(scene, scene.camera.samplePoint(rng));  // the pinhole, or a lens point
            lightSubpath(scene, rng, maxDepth, Heuristic::Power, light);
            PathExpression::State q = paths.start();
            for (int s = 1; s <= int(light.size()); ++s) {
                q = paths.step(q, s == 1 ? VertexType::L : surfaceType(scene, light[size_t(s - 1)].sp));
                if (prune && !paths.live(q)) break;
                if (!paths.accepting(paths.step(q, VertexType::E))) continue;
                const Connection c = connectCamera(scene, light.data(), s, z0);
                if (c.valid) task.splat.add(c.raster, c.value);
            }
        });
    }
};

}  // namespace

PS_REGISTER_PATH_FILTER(FilteredLightTracer, "lt");

}  // namespace ps
