// Lesson 11 — plumbing: `pm --paths EXPR`, lesson 8's photon mapper restricted to the paths an
// expression matches (path_filter.h), through lesson 8's photon visitor and gather estimate.
//
// Photons keep the light side of their path. A photon path is lesson 8's (tracePhoton), read
// forward from L by a photon visitor: the photon a vertex y stores carries, as its population, the
// forward state after y's own type (the string L ... T(y)), and the maps are one per population:
// one caustic map and one global map for each state a photon ends in (lesson 8's kd-tree and
// radiance estimate on each). At a dead state the visitor drops the photon and ends its walk.
//
// The camera side completes the string. The walk (lesson 3's) reads the backward automaton from E
// through the specular vertices to the first non-specular surface x, and adds, as pm does
// (Eq. 8.11), each term only for the paths that match:
//   - the emission it meets on the way (L S^j E) if reading L accepts;
//   - the light sample at x (L T(x) S^j E) if reading T(x), then L, accepts;
//   - the caustic maps of the states q that join the camera prefix E S^j (q holds T(x)): Eq. 11.5;
//   - the final gather (lesson 8's gatherRadiance), whose estimate at the non-specular y behind
//     c specular bounces is the global maps of the states that join E S^j T(x) S^c.
// With one state per map (`L.*E`) this is pm bit for bit: the same photon paths (pm's seeds),
// the same maps, the same random numbers on the camera side (tests/plumbing). With more states a
// density estimate gathers the k nearest photons of each state apart: each state's photons are a
// population of their own, whose density the estimate follows (consistent as pm is; its blur
// differs from pm's single map, so a filtered image is compared with filtered pt only up to pm's
// bias).
#include "08-photon-mapping/photonmap.h"
#include "11-classics/path_filter.h"
#include "tasks.h"

namespace ps {

namespace {

using State = PathExpression::State;

// A photon map per forward state (empty where no photon ended in that state).
struct StateMaps {
    std::vector<PhotonMap> byState;
    std::vector<State> states;  // those with photons, in increasing order
};

struct FilteredPhotonMapper : Integrator {
    explicit FilteredPhotonMapper(const PathExpression& e) : paths(e) {}
    PathExpression paths;

    std::vector<std::string> leftOut(const Scene& scene) const override {
        std::vector<std::string> lines = pathFilterLeftOut(
            paths, scene,
            "a photon path or a camera walk ends at its first vertex from which no path can match any more (a dead state, Eq. 11.6)");
        if (scene.settings.prune && !scene.caps.hasDeltaBSDF())
            lines.push_back("the caustic map: no specular surface, so no photon path L S+ D (lesson 8, Eq. 8.2)");
        return lines;
    }

    // Lesson 8's photon maps, one per forward state: each photon path's visitor reads L and then
    // every vertex's type, and files the photon under the state after its own.
    StateMaps traceMaps(const Scene& scene, MapKind kind, int emitted, int maxDepth, uint64_t seed, uint32_t iteration,
                        SampleStats& stats) const {
        const auto newVisitor = [&]() -> PhotonVisitor {
            return [this, &scene, q = paths.start()](const WalkVertex& v, Photon* photon) mutable {
                q = paths.step(q, v.bounces == 0 ? VertexType::L : surfaceType(scene, v.sp));
                if (photon) photon->population = q;
                return paths.live(q);
            };
        };
        StateMaps maps;
        maps.byState = tracePhotonPopulations(scene, kind, emitted, maxDepth, seed, iteration, stats, newVisitor);
        for (size_t s = 0; s < maps.byState.size(); ++s)
            if (maps.byState[s].size() > 0) maps.states.push_back(State(s));
        return maps;
    }

    // The density estimate at sp of the photons whose light prefix joins the camera side b.
    Color estimate(const StateMaps& maps, State b, const SurfacePoint& sp, const Material& m, const Vec3& wo,
                   const EstimateOptions& opt) const {
        Color L(0.0f);
        for (State q : maps.states)
            if (paths.joins(q, b)) L += radianceEstimate(maps.byState[q], sp, m, wo, opt);
        return L;
    }

    // pm's camera side (lesson 8's LiPhotonMap, Eq. 8.11) with a gather visitor that adds each
    // term only for the paths that match. The walk reaches x_k through specular bounces alone, so
    // the camera prefix before x_k is E S^k: prefix[k], its backward state.
    GatherVisitor gatherVisitor(const Scene& scene, const std::vector<State>& prefix, const StateMaps& caustic,
                                const StateMaps& global, const PmOptions& opt) const {
        const bool prune = scene.settings.prune;
        const auto type = [&scene](const SurfacePoint& sp) {
            return scatteringType(scene.materials[size_t(sp.material)]);
        };
        const auto acceptsLight = [this](State s) { return paths.backAccepting(paths.backStep(s, VertexType::L)); };
        GatherVisitor g;
        g.emission = [&prefix, acceptsLight](const WalkVertex& v) { return acceptsLight(prefix[size_t(v.bounces)]); };
        g.lightSample = [&prefix, acceptsLight, this, type](const WalkVertex& x) {
            return acceptsLight(paths.backStep(prefix[size_t(x.bounces)], type(x.sp)));
        };
        g.caustic = [&prefix, &caustic, &opt, this](const WalkVertex& x, const Material& m) {
            return estimate(caustic, prefix[size_t(x.bounces)], x.sp, m, x.wo, opt.causticEstimate);
        };
        // The global maps of the states that join E S^k T(x) S^c, c the specular bounces between
        // x and y.
        g.global = [&prefix, &global, &opt, this, type](const SurfacePoint& x, int xBounces, const SurfacePoint& y,
                                                        const Material& my, const Vec3& wo, int yBounces) {
            State b = paths.backStep(prefix[size_t(xBounces)], type(x));
            for (int k = xBounces + 1; k < yBounces; ++k) b = paths.backStep(b, VertexType::S);
            return estimate(global, b, y, my, wo, opt.globalEstimate);
        };
        if (prune)
            g.goesOn = [&prefix, this, type](const WalkVertex& v) {
                return paths.backLive(paths.backStep(prefix[size_t(v.bounces)], type(v.sp)));
            };
        return g;
    }

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        if (scene.settings.prune && !sceneCanMatch(paths, scene)) return;
        const PmOptions opt = pmOptions(scene);
        const int emitted = photonsPerMap(out);
        const StateMaps global = traceMaps(scene, MapKind::Global, emitted, opt.maxDepth,
                                           photonSeed(seed, MapKind::Global), iteration, stats);
        StateMaps caustic;
        if (!scene.settings.prune || scene.caps.hasDeltaBSDF())
            caustic = traceMaps(scene, MapKind::Caustic, emitted, opt.maxDepth, photonSeed(seed, MapKind::Caustic),
                                iteration, stats);
        std::vector<State> prefix(size_t(opt.maxDepth) + 1);  // E S^k, k = 0 .. maxDepth
        prefix[0] = paths.backStep(paths.backStart(), VertexType::E);
        for (size_t k = 1; k < prefix.size(); ++k) prefix[k] = paths.backStep(prefix[k - 1], VertexType::S);
        PmOptions filtered = opt;
        filtered.visitor = gatherVisitor(scene, prefix, caustic, global, opt);
        const PhotonMaps none;  // the visitor's maps stand for these
        renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task&) {
            const Ray ray = cameraRay(scene.camera, jitteredRaster(pixel, out.width, rng), rng);
            return LiPhotonMap(scene, ray, rng, none, filtered);
        });
    }
};

}  // namespace

PS_REGISTER_PATH_FILTER(FilteredPhotonMapper, "pm");

}  // namespace ps
