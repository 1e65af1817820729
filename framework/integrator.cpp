#include "integrator.h"
#include "errors.h"
#include "eyelight.h"
#include "tasks.h"

namespace ps {

void Integrator::setDeadline(double secondsFromNow, TimeClock clock) {
    hasDeadline_ = secondsFromNow > 0.0 && secondsFromNow < 1e9;  // also no NaN (a year is 3e7 s)
    deadlineClock_ = clock;
    if (hasDeadline_) deadline_ = clockSeconds(clock) + secondsFromNow;
}

void PixelIntegrator::renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                                      SampleStats& stats) {
    renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task&) {
        const Vec2 raster = jitteredRaster(pixel, out.width, rng);
        return Li(scene, cameraRay(scene.camera, raster, rng), rng);
    });
}

// The framework's own integrators (this file is linked into every program that makes one).
PS_REGISTER_INTEGRATOR(EyeLight, "eyelight",
                       "reflectance times |cos| between the normal and the eye ray at the first hit");
PS_REGISTER_INTEGRATOR(NormalView, "normals", "the surface normal at the first hit, mapped to colours (n + 1) / 2");

std::vector<IntegratorInfo> integratorList() {
    std::vector<IntegratorInfo> list;
    for (const auto& e : Registry<IntegratorInfo>::sorted()) list.push_back(e.value);
    return list;
}

std::unique_ptr<Integrator> makeIntegrator(const std::string& name) {
    const IntegratorInfo* info = Registry<IntegratorInfo>::find(name);
    if (!info) throw InputError("unknown algorithm '" + name + "' (known: " + Registry<IntegratorInfo>::names() + ")");
    std::unique_ptr<Integrator> made = info->make();
    made->name = name;
    made->caps = info->caps;
    return made;
}

std::vector<std::string> algorithmOptionNames() {
    std::vector<std::string> names;
    for (const auto& e : Registry<AlgorithmOption>::sorted()) names.push_back(e.name);
    return names;
}

bool takesAlgorithmOption(const std::string& algo) {
    for (const auto& e : Registry<AlgorithmOption>::sorted())
        for (const std::string& a : e.value.algorithms())
            if (a == algo) return true;
    return false;
}

std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const AlgorithmOptions& options) {
    std::unique_ptr<Integrator> plain = makeIntegrator(name);  // an unknown name says so first
    if (options.empty()) return plain;
    if (options.size() > 1)
        throw OptionError("algorithm options cannot be combined (--" + options[0].first + " and --" + options[1].first +
                          ")");
    const auto& [option, value] = options[0];
    const AlgorithmOption* o = Registry<AlgorithmOption>::find(option);
    if (!o) throw OptionError("unknown algorithm option '--" + option + "'");
    o->check(value);
    std::unique_ptr<Integrator> made = o->make(name, value);
    if (!made) {
        std::string can;
        for (const std::string& a : o->algorithms()) can += (can.empty() ? "" : ", ") + a;
        throw OptionError("algorithm '" + name + "' does not take --" + option + " (" + o->valueName + " '" + value +
                          "'); these do: " + (can.empty() ? std::string("none") : can));
    }
    made->name = name;
    made->caps = plain->caps;  // the algorithm's, whatever form the option gave it
    return made;
}

}  // namespace ps
