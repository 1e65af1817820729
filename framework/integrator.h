// Integrators are progressive: one iteration renders one sample per pixel (or one batch of
// light paths) into an image of its own; the film averages the iterations.
#pragma once
#include <memory>
#include <string>
#include <vector>
#include "film.h"
#include "rng.h"
#include "scene.h"

namespace ps {

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
    // What the integrator counted during the render, one line each (lesson 10: path vertices,
    // splits, roulette), printed by the render command after its summary. Empty by default.
    virtual std::vector<std::string> report() const { return {}; }
    // Whether it renders a thin-lens camera (lesson 11) correctly. render() refuses a lens scene
    // otherwise (InputError), rather than render it as something else. False unless an
    // integrator says so: PixelIntegrator does (the framework's pixel loop makes lens rays).
    virtual bool rendersThinLens() const { return false; }
    std::string name;  // the algorithm's name (makeIntegrator sets it), for messages
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

}  // namespace ps
