// Lesson 11 — plumbing: `bpt --paths EXPR` (and bpt-balance, bpt-full), lesson 7's bidirectional
// path tracer restricted to the paths an expression matches (path_filter.h): before technique
// (s, t) connects, BptOptions::techniqueFilter (bptPathMatches) joins the light prefix, read forward,
// with the camera prefix, read backward (Eq. 11.5). A path's string does not depend on the
// technique that sampled it, so the MIS weights of the techniques that can sample a matching path
// still add up to one: the filtered image is the integral over the matching paths (Eq. 11.5).
// The subpaths and the random numbers of s = 1 are the same as without the filter; only the
// connections of paths that do not match are skipped (with their shadow rays).
//
// A thin-lens camera (lesson 11): the camera subpath starts on the lens, and the technique t = 0
// (lens_technique.cpp: a light subpath that reaches the lens) asks pathTest too, with the lens
// point as the path's E (bptPathMatches with t = 0), after its step's random numbers are drawn.
#include "11-classics/path_filter.h"
#include "tasks.h"

namespace ps {

namespace {

struct FilteredBpt : Integrator {
    FilteredBpt(const PathExpression& e, Heuristic h, bool recursive) : paths(e) {
        opt.heuristic = h;
        opt.recursive = recursive;
        techniques = bptTechniqueRenderer([this](const Scene& scene) { return filtered(scene); });
    }
    PathExpression paths;
    BptOptions opt;

    // The options with lesson 7's technique filter: the technique's path must match (valid while
    // scene is).
    BptOptions filtered(const Scene& scene) const {
        BptOptions o = opt;
        o.techniqueFilter = [this, &scene](const Subpath& light, const Subpath& camera, int s, int t) {
            return bptPathMatches(paths, scene, light, camera, s, t);
        };
        return o;
    }

    std::vector<std::string> leftOut(const Scene& scene) const override {
        std::vector<std::string> lines = bptLeftOut(scene, opt);
        for (const std::string& l : pathFilterLeftOut(
                 paths, scene, "a technique connects (traces its shadow ray) only where its path matches"))
            lines.push_back(l);
        return lines;
    }

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        if (scene.settings.prune && !sceneCanMatch(paths, scene)) return;
        const BptOptions o = filtered(scene);
        renderPixelTasks(seed, iteration, out, stats, true, [&](int pixel, Rng& rng, Task& task) {
            const Vec2 raster = jitteredRaster(pixel, out.width, rng);
            return bptSample(scene, raster, rng, o, task.splat, nullptr);
        });
    }
};

struct FilteredBptPower : FilteredBpt {
    explicit FilteredBptPower(const PathExpression& e) : FilteredBpt(e, Heuristic::Power, true) {}
};
struct FilteredBptBalance : FilteredBpt {
    explicit FilteredBptBalance(const PathExpression& e) : FilteredBpt(e, Heuristic::Balance, true) {}
};
struct FilteredBptFull : FilteredBpt {
    explicit FilteredBptFull(const PathExpression& e) : FilteredBpt(e, Heuristic::Power, false) {}
};

}  // namespace

PS_REGISTER_PATH_FILTER(FilteredBptPower, "bpt");
PS_REGISTER_PATH_FILTER(FilteredBptBalance, "bpt-balance");
PS_REGISTER_PATH_FILTER(FilteredBptFull, "bpt-full");

}  // namespace ps
