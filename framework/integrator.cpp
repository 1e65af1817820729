#include "integrator.h"
#include "errors.h"
#include <algorithm>
#include <map>
#include "eyelight.h"
#include "tasks.h"

namespace ps {

void Integrator::setDeadline(double secondsFromNow) {
    using namespace std::chrono;
    hasDeadline_ = secondsFromNow > 0.0 && secondsFromNow < 1e9;  // also no NaN (a year is 3e7 s)
    if (hasDeadline_)
        deadline_ = steady_clock::now() + duration_cast<steady_clock::duration>(duration<double>(secondsFromNow));
}

void PixelIntegrator::renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                                      SampleStats& stats) {
    renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task&) {
        const Vec2 raster = jitteredRaster(pixel, out.width, rng);
        return Li(scene, cameraRay(scene.camera, raster, rng), rng);
    });
}

namespace {
// The framework's own integrators, then whatever the lessons register during static
// initialisation (lesson code is linked as object files, so its registrations are kept).
std::vector<IntegratorInfo>& registry() {
    static std::vector<IntegratorInfo> list = {
        {"eyelight", "reflectance times |cos| between the normal and the eye ray at the first hit",
         [] { return std::unique_ptr<Integrator>(std::make_unique<EyeLight>()); }},
        {"normals", "the surface normal at the first hit, mapped to colours (n + 1) / 2",
         [] { return std::unique_ptr<Integrator>(std::make_unique<NormalView>()); }},
    };
    return list;
}
}  // namespace

bool registerIntegrator(const IntegratorInfo& info) {
    registry().push_back(info);
    return true;
}

std::vector<IntegratorInfo> integratorList() {
    std::vector<IntegratorInfo> list = registry();
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    return list;
}

std::unique_ptr<Integrator> makeIntegrator(const std::string& name) {
    for (const IntegratorInfo& i : registry())
        if (i.name == name) {
            std::unique_ptr<Integrator> made = i.make();
            made->name = name;
            return made;
        }
    std::string known;
    for (const auto& i : integratorList()) known += (known.empty() ? "" : ", ") + i.name;
    throw InputError("unknown algorithm '" + name + "' (known: " + known + ")");
}

namespace {
std::map<std::string, PathFilteredMaker>& pathFilters() {
    static std::map<std::string, PathFilteredMaker> filters;
    return filters;
}
}  // namespace

bool registerPathFilter(const std::string& name, PathFilteredMaker make) {
    pathFilters()[name] = make;
    return true;
}

std::vector<std::string> pathFilteredAlgorithms() {
    std::vector<std::string> names;
    for (const auto& [name, make] : pathFilters()) names.push_back(name);
    return names;
}

bool honoursPaths(const std::string& name) { return pathFilters().count(name) > 0; }

std::unique_ptr<Integrator> makeIntegrator(const std::string& name, const PathExpression* paths) {
    if (!paths) return makeIntegrator(name);
    const auto it = pathFilters().find(name);
    if (it != pathFilters().end()) {
        std::unique_ptr<Integrator> made = it->second(*paths);
        made->name = name;
        return made;
    }
    makeIntegrator(name);  // an unknown name says so first
    std::string can;
    for (const std::string& n : pathFilteredAlgorithms()) can += (can.empty() ? "" : ", ") + n;
    throw InputError("algorithm '" + name + "' cannot render only the paths of an expression (--paths '" +
                     paths->text() + "'); these can: " + (can.empty() ? std::string("none") : can));
}

}  // namespace ps
