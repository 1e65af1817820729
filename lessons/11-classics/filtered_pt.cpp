// Lesson 11 — plumbing: `pt --paths EXPR`, lesson 3's path tracer (next-event estimation and BSDF
// hits combined by MIS) restricted to the paths an expression matches (path_filter.h).
//
// The camera walk reads the backward automaton: E, then the type of every vertex it meets. At
// vertex x_k (state b after E x_1 .. x_{k-1}) lesson 3's two halves of pt's MIS are kept apart:
//   - misEmission, the emission the walk found at x_k: the path whose light is x_k, kept if
//     reading L next accepts (Eq. 11.5);
//   - misLightSample, the light sample: the path x_k then a new light vertex, kept if reading
//     x_k's type and then L accepts.
// A rejected light sample is still drawn (and thrown away), so the walk meets
// the same random numbers whatever the expression: images of complementary expressions with the
// same seed add up to pt's image, and `L.*E` gives pt's image bit for bit (tests/framework/paths).
// Where no path through the walk can match any more (Eq. 11.6) the walk ends: the pixel's other
// contributions would all be rejected, and every pixel has its own random numbers, so ending it
// changes nothing (`--no-prune` walks on, to check that).
#include <atomic>
#include "11-classics/path_filter.h"

namespace ps {

namespace {

struct FilteredPathTracer : PixelIntegrator {
    explicit FilteredPathTracer(const PathExpression& e) : paths(e) {}
    PathExpression paths;
    mutable std::atomic<uint64_t> walks{0}, ended{0};

    std::vector<std::string> leftOut(const Scene& scene) const override {
        return pathFilterLeftOut(
            paths, scene,
            "a camera walk ends at its first vertex from which no path can match any more (a dead state, Eq. 11.6)");
    }
    std::vector<std::string> report() const override {
        return {"camera walks ended early (no path through them matches '" + paths.text() +
                "'): " + std::to_string(ended.load()) + " of " + std::to_string(walks.load())};
    }

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        if (scene.settings.prune && !sceneCanMatch(paths, scene)) return;  // black: nothing can match
        PixelIntegrator::renderIteration(scene, iteration, seed, out, stats);
    }

    Color Li(const Scene& scene, const Ray& ray, Rng& rng) const override {
        const int maxDepth = scene.settings.maxDepth;
        const bool prune = scene.settings.prune;
        Color L(0.0f);
        ++walks;
        PathExpression::State b = paths.backStep(paths.backStart(), VertexType::E);
        cameraWalk(scene, ray, rng, {maxDepth}, [&](const WalkVertex& v) {
            // The path whose light is x_k: L, then x_{k-1} .. x_1 (read), then E.
            if (paths.backAccepting(paths.backStep(b, VertexType::L))) L += misEmission(scene, v);
            if (!v.hit) return false;
            const PathExpression::State here = paths.backStep(b, surfaceType(scene, v.sp));
            const bool live = paths.backLive(here);
            if (prune && !live) {
                ++ended;
                return false;
            }
            // The light sample at x_k: a new light vertex, then x_k .. x_1, then E. Drawn whether
            // it matches or not, so that the walk meets the same numbers.
            const Color sample = misLightSample(scene, v, rng, maxDepth);
            if (paths.backAccepting(paths.backStep(here, VertexType::L))) L += sample;
            b = here;
            return true;
        });
        return L;
    }
};

}  // namespace

PS_REGISTER_PATH_FILTER(FilteredPathTracer, "pt");

}  // namespace ps
