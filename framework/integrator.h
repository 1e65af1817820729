// Integrators are progressive: one iteration renders one sample per pixel (or one batch of
// light paths) into an image of its own; the film averages the iterations.
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include "film.h"
#include "registry.h"
#include "rng.h"
#include "scene.h"
#include "stopwatch.h"

namespace ps {

// What an integrator can do beyond what every one does: data given at registration, not code.
struct IntegratorCaps {
    // It renders a camera model other than the pinhole (camera.h) by asking the camera for its
    // points, rays and importance; render() refuses such a scene otherwise (an InputError naming
    // the algorithms that can), rather than render it as something else.
    bool cameraModels = false;
    // Every iteration's image is its whole current estimate, not one more sample of it (an
    // iterative solver): the render loop keeps the latest image instead of the mean (its variance
    // of the mean is 0).
    bool latestIterationIsImage = false;
    // Throws InputError, naming what it does not support, if the integrator cannot render the
    // scene at all; render() and the commands call it before anything else. nullptr: every scene.
    void (*checkScene)(const Scene& scene) = nullptr;

    IntegratorCaps& withCameraModels() {
        cameraModels = true;
        return *this;
    }
    IntegratorCaps& withLatestIterationIsImage() {
        latestIterationIsImage = true;
        return *this;
    }
    IntegratorCaps& withSceneCheck(void (*check)(const Scene&)) {
        checkScene = check;
        return *this;
    }
    // It renders per-technique images (Integrator::techniques): `pathspace pyramid` takes it.
    bool techniqueImages = false;
    IntegratorCaps& withTechniqueImages() {
        techniqueImages = true;
        return *this;
    }
};

// ---- per-technique images (Veach's pyramid, `pathspace pyramid`) -------------------------------
// An integrator that combines several sampling techniques of the same paths can render each
// technique's estimate alone (unweighted) and MIS-weighted, one row per path length.
struct TechniqueCell {
    std::string name;   // for file names: "1-2" (s = 1, t = 2)
    std::string label;  // drawn over its image: "(1,2)"
    Image unweighted, weighted;
};
struct TechniqueRow {
    std::string label;  // "k=2"
    std::vector<TechniqueCell> cells;
};
struct TechniqueImagesOptions {
    int maxLength = 4;  // path lengths 1 .. maxLength (edges)
    int spp = 1;
    uint64_t seed = 0;
    int threads = 0;  // 0: all cores; the images do not depend on it
};
struct TechniquePyramid {
    std::vector<TechniqueRow> rows;
    SampleStats stats;  // NaN/Inf values met (counted, left out of the images)
};
// What an integrator offers for them (Integrator::techniques): the rows' cells without images
// (their names, to check the files before anything renders), and the images.
struct TechniqueRenderer {
    std::function<std::vector<TechniqueRow>(int maxLength)> layout;
    std::function<TechniquePyramid(const Scene& scene, const TechniqueImagesOptions& opt)> render;
};

class Integrator {
public:
    virtual ~Integrator() = default;
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
    // What the integrator counted during the render (paths, splits, shooting steps), one line
    // each, printed by the render command after its summary. Empty by default.
    virtual std::vector<std::string> report() const { return {}; }

    std::string name;     // the algorithm's name (makeIntegrator sets it), for messages
    IntegratorCaps caps;  // what it can do (makeIntegrator sets it from the registration)
    // Per-technique images of this integrator, as configured (set where caps.techniqueImages).
    TechniqueRenderer techniques;

    // The render loop's time budget (--time). render() sets the deadline before each iteration,
    // or none without a budget. An integrator whose one iteration can outlast the budget (an
    // iterative solver whose iteration is hundreds of steps, each of up to a million numbers)
    // asks timeIsUp() between pieces of its work and ends the iteration early, with an image
    // that is a valid estimate. Without a deadline every iteration is whole, and a function of
    // (scene, iteration, seed) as renderIteration says; with one, a cut iteration depends on
    // the time, as the number of iterations of a timed render does.
    // The deadline is on the render's clock (--clock: wall or the process's CPU time).
    bool timeIsUp() const { return hasDeadline_ && clockSeconds(deadlineClock_) >= deadline_; }
    // A budget that is not positive and finite: none.
    void setDeadline(double secondsFromNow, TimeClock clock = TimeClock::Wall);
    // What is left of the render's budget as an iteration starts (render() sets both before each
    // one): the seconds to the deadline on the render's clock (infinity without --time), and the
    // iterations still to render, this one included (-1 without --spp). An integrator that learns
    // while it renders (a radiance field it samples) stops learning where nothing after would use
    // what it learns (with --time, what it decides depends on the time, as the number of
    // iterations of a timed render does).
    double secondsLeft() const { return hasDeadline_ ? deadline_ - clockSeconds(deadlineClock_) : kInf; }
    int iterationsLeft() const { return iterationsLeft_; }
    void setIterationsLeft(int iterations) { iterationsLeft_ = iterations; }

private:
    int iterationsLeft_ = -1;
    bool hasDeadline_ = false;
    TimeClock deadlineClock_ = TimeClock::Wall;
    double deadline_ = 0.0;  // clockSeconds(deadlineClock_) at the deadline
};

// An integrator that estimates the radiance along one camera ray per pixel per iteration. The
// framework's pixel loop makes the ray, through the camera's model if it has one (tasks.h).
class PixelIntegrator : public Integrator {
public:
    PixelIntegrator() { caps.cameraModels = true; }
    // Radiance arriving at the camera along ray.
    virtual Color Li(const Scene& scene, const Ray& ray, Rng& rng) const = 0;
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override;
};

// One registered algorithm (Registry<IntegratorInfo>, keyed by name).
struct IntegratorInfo {
    std::string name, description;
    std::unique_ptr<Integrator> (*make)() = nullptr;
    IntegratorCaps caps;
};
// The integrators the render command knows, sorted by name.
std::vector<IntegratorInfo> integratorList();
// Throws InputError naming the unknown algorithm and the known ones.
std::unique_ptr<Integrator> makeIntegrator(const std::string& name);

// The registration's capabilities of Type: caps, and camera models for a PixelIntegrator (its
// rays come from the framework's pixel loop).
template <class Type>
IntegratorCaps integratorCaps(IntegratorCaps caps = IntegratorCaps()) {
    if (std::is_base_of<PixelIntegrator, Type>::value) caps.cameraModels = true;
    return caps;
}

// In a lesson's .cpp at namespace scope; _CAPS gives capabilities, e.g.
// PS_REGISTER_INTEGRATOR_CAPS(LightTracer, "lt", "...", IntegratorCaps().withCameraModels()).
#define PS_REGISTER_INTEGRATOR_CAPS(Type, name, description, caps)                                                \
    static const bool psRegistered_##Type = ::ps::Registry<::ps::IntegratorInfo>::add(                            \
        name, {name, description, []() -> std::unique_ptr<::ps::Integrator> { return std::make_unique<Type>(); }, \
               ::ps::integratorCaps<Type>(caps)})
#define PS_REGISTER_INTEGRATOR(Type, name, description) \
    PS_REGISTER_INTEGRATOR_CAPS(Type, name, description, ::ps::IntegratorCaps())

// ---- algorithm options -------------------------------------------------------------------------
// An option some algorithms take on the command line (--NAME VALUE in render, converge, pyramid),
// given its meaning by the lesson that registers it (Registry<AlgorithmOption>, keyed by NAME): it
// makes such an algorithm's integrator from the option's value. Every algorithm that does not take
// a given option refuses it: an option is never ignored.
struct AlgorithmOption {
    std::string valueName;  // in the usage: "--NAME VALUENAME"
    std::string help;       // the usage paragraph of the option, ending in a newline
    // The algorithms that take it, sorted (the help marks them).
    std::vector<std::string> (*algorithms)() = nullptr;
    // Throws OptionError saying what is wrong with a value (called before any scene is loaded).
    void (*check)(const std::string& value) = nullptr;
    // Algorithm algo's integrator with the option's value, nullptr if algo does not take it.
    std::unique_ptr<Integrator> (*make)(const std::string& algo, const std::string& value) = nullptr;
};
// The options given to an algorithm: (NAME, VALUE) pairs.
using AlgorithmOptions = std::vector<std::pair<std::string, std::string>>;
// makeIntegrator(name) for no option; else the integrator the option makes. InputError for an
// unknown algorithm; OptionError for an unknown option, a bad value, more than one option, or an
// algorithm that does not take the option ("algorithm 'X' does not take --NAME; these do: ...").
std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const AlgorithmOptions& options);
// The registered options' names, sorted.
std::vector<std::string> algorithmOptionNames();
// Whether algorithm `algo` takes some registered option (help marks it).
bool takesAlgorithmOption(const std::string& algo);

}  // namespace ps
