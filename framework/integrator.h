// Integrators are progressive: one iteration renders one sample per pixel (or one batch of
// light paths) into an image of its own; the film averages the iterations.
#pragma once
#include <chrono>
#include <memory>
#include <string>
#include <vector>
#include "film.h"
#include "path_expression.h"
#include "rng.h"
#include "scene.h"

namespace ps {

class Integrator {
public:
    virtual ~Integrator() = default;
    // Throws InputError, naming what it does not support, if this integrator cannot render the
    // scene at all (lesson 11's radiosity: diffuse quads and area lights only). render() calls it
    // first. The default accepts every scene.
    virtual void checkScene(const Scene&) const {}
    // Scene-dependent preprocessing (a photon pass, a bootstrap); counted in render time.
    virtual void prepare(const Scene&) {}
    // What this integrator leaves out on this scene because the scene's capabilities show it
    // cannot contribute, one line each with the reason, e.g. "s = 0 techniques: no light can be
    // hit (point lights only)". Empty when nothing is left out or scene.settings.prune is false.
    // Pruning must be exact: the image's expectation is the same either way. The render and
    // converge commands print these lines.
    virtual std::vector<std::string> leftOut(const Scene&) const { return {}; }
    // Renders iteration `iteration` into out (zeroed, film-sized). Must be a function of
    // (scene, iteration, seed) only, never of the thread count.
    virtual void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                                 SampleStats& stats) = 0;
    // What the integrator counted during the render, one line each (lesson 10: path vertices,
    // splits, roulette), printed by the render command after its summary. Empty by default.
    virtual std::vector<std::string> report() const { return {}; }
    // The paths whose contribution this integrator estimates on this scene, as a Heckbert path
    // expression (path_expression.h, lesson 11): every path by default (kAllPaths). A classic of
    // lesson 11 carries fewer (whitted: "L[DG]S*E|LS*E" where every light is a point light), and
    // returns "" where no expression over the alphabet says which (whitted on a scene with an
    // area light, which it shows but lights nothing with). The extreme tests compare an
    // integrator with pt filtered to its expression.
    virtual std::string carriedPaths(const Scene&) const { return kAllPaths; }
    static constexpr const char* kAllPaths = "L.*E";
    // True for an integrator whose every iteration's image is its whole current estimate, not
    // one more sample of it (lesson 11's radiosity: iteration k shows the solution after k
    // batches of shooting steps). The render loop then keeps only the latest image instead of
    // averaging them (its variance of the mean is 0).
    virtual bool latestIterationIsImage() const { return false; }
    // Whether it renders a thin-lens camera (lesson 11) correctly. render() refuses a lens scene
    // otherwise (InputError), rather than render it as something else. False unless an
    // integrator says so: PixelIntegrator does (the framework's pixel loop makes lens rays).
    virtual bool rendersThinLens() const { return false; }
    std::string name;  // the algorithm's name (makeIntegrator sets it), for messages

    // The render loop's time budget (--time). render() sets the deadline before each iteration,
    // or none without a budget. An integrator whose one iteration can outlast the budget (lesson
    // 11's radiosity: hundreds of shooting steps, each a row of up to a million form factors)
    // asks timeIsUp() between pieces of its work and ends the iteration early, with an image
    // that is a valid estimate. Without a deadline every iteration is whole, and a function of
    // (scene, iteration, seed) as renderIteration says; with one, a cut iteration depends on
    // the time, as the number of iterations of a timed render does.
    bool timeIsUp() const { return hasDeadline_ && std::chrono::steady_clock::now() >= deadline_; }
    void setDeadline(double secondsFromNow);  // a budget that is not positive and finite: none

private:
    bool hasDeadline_ = false;
    std::chrono::steady_clock::time_point deadline_;
};

// An integrator that estimates the radiance along one camera ray per pixel per iteration.
class PixelIntegrator : public Integrator {
public:
    // Radiance arriving at the camera along ray.
    virtual Color Li(const Scene& scene, const Ray& ray, Rng& rng) const = 0;
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override;
    bool rendersThinLens() const override { return true; }
};

struct IntegratorInfo {
    std::string name, description;
    std::unique_ptr<Integrator> (*make)();
};
// Adds an integrator to the list the render command knows; returns true. Lessons register
// theirs with PS_REGISTER_INTEGRATOR at namespace scope in their .cpp file.
bool registerIntegrator(const IntegratorInfo& info);
// The integrators the render command knows, sorted by name.
std::vector<IntegratorInfo> integratorList();
// Throws InputError naming the unknown algorithm and the known ones.
std::unique_ptr<Integrator> makeIntegrator(const std::string& name);

#define PS_REGISTER_INTEGRATOR(Type, name, description)               \
    static const bool psRegistered_##Type = ::ps::registerIntegrator( \
        {name, description, []() -> std::unique_ptr<::ps::Integrator> { return std::make_unique<Type>(); }})

// ---- Heckbert's path expressions (`--paths`, path_expression.h, lesson 11) ----------------------
// An algorithm that can render only the paths an expression matches registers a second form of
// itself under the same name: an integrator made from the compiled expression. Every other
// algorithm refuses an expression (makeIntegrator below): an expression is never ignored.
using PathFilteredMaker = std::unique_ptr<Integrator> (*)(const PathExpression& paths);
bool registerPathFilter(const std::string& name, PathFilteredMaker make);
// The algorithms that honour an expression, sorted by name.
std::vector<std::string> pathFilteredAlgorithms();
bool honoursPaths(const std::string& name);
// paths == nullptr: makeIntegrator(name). Otherwise the algorithm's filtered form; InputError if
// the name is unknown or the algorithm has none ("algorithm 'X' cannot render only the paths of
// an expression (--paths); these can: ...").
std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const PathExpression* paths);

// In a lesson's .cpp at namespace scope: Type has a constructor Type(const PathExpression&).
#define PS_REGISTER_PATH_FILTER(Type, name)                                                                         \
    static const bool psPathFilter_##Type =                                                                         \
        ::ps::registerPathFilter(name, [](const ::ps::PathExpression& paths) -> std::unique_ptr<::ps::Integrator> { \
            return std::make_unique<Type>(paths);                                                                   \
        })

}  // namespace ps
