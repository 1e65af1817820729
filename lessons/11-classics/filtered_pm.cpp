// Lesson 11 — plumbing: `pm --paths EXPR`, lesson 8's photon mapper restricted to the paths an
// expression matches (path_filter.h).
//
// Photons keep the light side of their path. A photon path is lesson 5's light walk read forward
// from L; the photon a vertex y stores carries the forward state after y's own type (the string
// L ... T(y)), and the maps are built per state: one caustic map and one global map for each
// state a photon ends in (lesson 8's kd-tree and radiance estimate on each). A photon whose state
// is dead is not stored, and its walk ends there.
//
// The camera side completes the string. The walk reads the backward automaton from E through
// the specular vertices to the first non-specular surface x, and adds, as pm does (Eq. 8.11):
//   - the emission it meets on the way (L S^j E) if reading L accepts;
//   - the light sample at x (L T(x) S^j E) if reading T(x), then L, accepts;
//   - the caustic maps of the states q that join the camera prefix E S^j (q holds T(x)): Eq. 11.5;
//   - the final gather: one BSDF sample from x, followed through specular surfaces to a
//     non-specular y, and there the global maps of the states that join E S^j T(x) S^c.
// With one state per map (`L.*E`) this is pm bit for bit: the same photon paths (pm's seeds),
// the same maps, the same random numbers on the camera side (tests/framework/paths). With more
// states a density estimate gathers the k nearest photons of each state apart: each state's
// photons are a population of their own, whose density the estimate follows (consistent as
// pm is; its blur differs from pm's single map, so a filtered image is compared with filtered
// pt only up to pm's bias).
//
// This file re-implements pm's camera side and photon storage (lesson 8's LiPhotonMap,
// gatherRadiance and tracePhoton) to carry the states: it is the lecturer's, left out of the
// student handout (scripts/handout.sh) like tools/photon_figures.cpp; there `pm --paths` is
// refused as any algorithm without a filtered form is.
#include "08-photon-mapping/photonmap.h"
#include "11-classics/path_filter.h"
#include "tasks.h"

namespace ps {

namespace {

// pm's (lessons/08-photon-mapping/pm_integrator.cpp): photon paths per map and per iteration,
// the seeds' salts, the estimates' settings.
constexpr int kMinPhotons = 8192;
constexpr uint64_t kGlobalSalt = 0x8A1F0C3D5B7E9246ull, kCausticSalt = 0x3C6EF372FE94F82Bull;

PmOptions pmOptions(const Scene& scene) {
    PmOptions opt;
    opt.maxDepth = scene.settings.maxDepth;
    opt.globalEstimate.filter = Filter::Box;
    opt.globalEstimate.k = 50;
    opt.globalEstimate.maxRadius = 0.1f * scene.radius;
    opt.causticEstimate.filter = Filter::Cone;
    opt.causticEstimate.k = 50;
    opt.causticEstimate.maxRadius = 0.02f * scene.radius;
    return opt;
}

using State = PathExpression::State;

// A photon map per forward state (empty where no photon ended in that state).
struct StateMaps {
    std::vector<PhotonMap> byState;
    std::vector<State> states;  // those with photons, in increasing order
};

struct TypedPhoton {
    Photon photon;
    State state;
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

    // One photon path (pm's tracePhoton, Eq. 8.1-8.3), its photons tagged with their states.
    void tracePhotonPath(const Scene& scene, Rng& rng, int maxDepth, MapKind kind, int emitted,
                         std::vector<TypedPhoton>& out) const {
        const bool prune = scene.settings.prune;
        bool onlySpecular = true;
        const float invN = 1.0f / float(emitted);
        State q = paths.step(paths.start(), VertexType::L);
        lightWalk(scene, rng, {maxDepth, photonSurvival}, [&](const WalkVertex& v, const LightPathStart&) {
            if (v.bounces == 0) return !prune || paths.live(q);
            const Material& m = scene.materials[size_t(v.sp.material)];
            q = paths.step(q, scatteringType(m));
            if (!m.isDelta()) {
                if ((kind == MapKind::Global || (onlySpecular && v.bounces >= 2)) && paths.live(q)) {
                    TypedPhoton t;
                    t.photon.p = v.sp.p;
                    t.photon.power = v.beta * invN;
                    t.photon.setWLight(v.wo);
                    t.state = q;
                    out.push_back(t);
                }
                onlySpecular = false;
                if (kind == MapKind::Caustic) return false;
            }
            return !prune || paths.live(q);
        });
    }

    // pm's tracePhotonMap, into one map per state (photons in path order within each).
    StateMaps traceMaps(const Scene& scene, MapKind kind, int emitted, int maxDepth, uint64_t seed, uint32_t iteration,
                        SampleStats& stats) const {
        std::vector<std::vector<TypedPhoton>> perTask(size_t(taskCount(emitted)));
        runTasks(TaskLoop(emitted, seed, iteration), stats, [&](int, Rng& rng, Task& task) {
            tracePhotonPath(scene, rng, maxDepth, kind, emitted, perTask[task.index]);
        });
        std::vector<std::vector<Photon>> byState(size_t(paths.states()));
        for (const auto& list : perTask)
            for (const TypedPhoton& t : list)
                if (isFinite(t.photon.power)) byState[t.state].push_back(t.photon);
                else checkSample(t.photon.power, stats);
        StateMaps maps;
        maps.byState.resize(byState.size());
        for (size_t s = 0; s < byState.size(); ++s) {
            maps.byState[s].emitted = emitted;
            if (byState[s].empty()) continue;
            maps.states.push_back(State(s));
            buildPhotonMap(std::move(byState[s]), maps.byState[s]);
        }
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

    // pm's LiPhotonMap (Eq. 8.11), each term added only for the paths that match.
    Color Li(const Scene& scene, const Ray& ray, Rng& rng, const StateMaps& caustic, const StateMaps& global,
             const PmOptions& opt) const {
        const bool prune = scene.settings.prune;
        Color L(0.0f);
        State b = paths.backStep(paths.backStart(), VertexType::E);
        const auto acceptsLight = [&](State s) { return paths.backAccepting(paths.backStep(s, VertexType::L)); };
        cameraWalk(scene, ray, rng, {opt.maxDepth}, [&](const WalkVertex& v) {
            if (!v.hit) {
                if (v.specular && acceptsLight(b)) L += v.beta * scene.backgroundRadiance();
                return false;
            }
            if (v.specular && v.sp.light >= 0 && acceptsLight(b))
                L += v.beta * emittedRadiance(scene.lights[size_t(v.sp.light)], v.sp.n, v.wo);
            const Material& m = scene.materials[size_t(v.sp.material)];
            const State here = paths.backStep(b, scatteringType(m));
            if (m.isDelta()) {
                b = here;
                return !prune || paths.backLive(b);
            }
            if (v.bounces < opt.maxDepth) {
                const float uLight = rng.uniform();
                const Vec2 uPoint = rng.uniform2();
                if (acceptsLight(here)) L += v.beta * sampleDirectLight(scene, v.sp, v.wo, uLight, uPoint).value;
            }
            L += v.beta * estimate(caustic, b, v.sp, m, v.wo, opt.causticEstimate);
            if (v.bounces >= opt.maxDepth || (prune && !paths.backLive(here))) return false;
            // The final gather from x, through specular surfaces to y (pm's gatherRadiance).
            BSDFSample s;
            const Vec2 u = rng.uniform2();
            const float uLobe = rng.uniform();
            if (!sampleBSDF(m, v.sp.n, v.wo, u, uLobe, Transport::Radiance, s)) return false;
            Color weight = v.beta * s.weight;
            Ray gather = scene.spawnRay(v.sp, s.wi);
            State g = here;
            for (int k = v.bounces + 1; k <= opt.maxDepth && !isBlack(weight); ++k) {
                SurfacePoint y;
                if (!scene.intersect(gather, y)) break;
                const Material& my = scene.materials[size_t(y.material)];
                if (!my.isDelta()) {
                    L += weight * estimate(global, g, y, my, -gather.d, opt.globalEstimate);
                    break;
                }
                g = paths.backStep(g, VertexType::S);
                if (prune && !paths.backLive(g)) break;
                BSDFSample t;
                const Vec2 ut = rng.uniform2();
                const float uLobeT = rng.uniform();
                if (!sampleBSDF(my, y.n, -gather.d, ut, uLobeT, Transport::Radiance, t)) break;
                weight *= t.weight;
                gather = scene.spawnRay(y, t.wi);
            }
            return false;
        });
        return L;
    }

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        if (scene.settings.prune && !sceneCanMatch(paths, scene)) return;
        const PmOptions opt = pmOptions(scene);
        const int emitted = std::max(kMinPhotons, out.width * out.height);
        const StateMaps global =
            traceMaps(scene, MapKind::Global, emitted, opt.maxDepth, seed ^ kGlobalSalt, iteration, stats);
        StateMaps caustic;
        if (!scene.settings.prune || scene.caps.hasDeltaBSDF())
            caustic = traceMaps(scene, MapKind::Caustic, emitted, opt.maxDepth, seed ^ kCausticSalt, iteration, stats);
        renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task&) {
            const Ray ray = cameraRay(scene.camera, jitteredRaster(pixel, out.width, rng), rng);
            return Li(scene, ray, rng, caustic, global, opt);
        });
    }
};

}  // namespace

PS_REGISTER_PATH_FILTER(FilteredPhotonMapper, "pm");

}  // namespace ps
