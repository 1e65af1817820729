// Lesson 11 — plumbing: the Whitted ray tracer the render command knows as `whitted` (read it,
// nothing to write here). One camera ray through a jittered point of every pixel per iteration,
// estimated by LiWhitted (whitted.h, Eq. 11.9) with the scene's maximum depth and ambient term
// (`render maxdepth D ambient R G B` in the scene file, `--maxdepth`, `--ambient` on the command
// line: `ambient` is a render parameter this lesson registers, framework/scene.h). Nothing in it is random but the pixel's jitter: its iterations only antialias.
//
// Glass splits every ray in two, so a path through glass costs up to 2^maxdepth rays: keep the
// maximum depth small where there is glass (the lesson's scenes use 6).
#include "11-classics/path_filter.h"
#include "11-classics/whitted.h"
#include "integrator.h"

namespace ps {

namespace {
[[maybe_unused]] const bool ambientRegistered = Registry<RenderParameter>::add(
    "ambient", {"whitted: the ambient radiance, added times the albedo at every non-specular surface (default 0)",
                "R G B", 3, [](const std::vector<float>& v) {
                    for (float x : v)
                        if (!(x >= 0.0f && x <= 1e30f)) return std::string("must not be negative nor above 1e30");
                    return std::string();
                }});
}  // namespace

Color whittedAmbient(const RenderSettings& settings) {
    const std::vector<float> v = renderParameterValues(settings, "ambient", {0.0f, 0.0f, 0.0f});
    return Color(v[0], v[1], v[2]);
}

namespace {

struct Whitted : PixelIntegrator {
    static WhittedOptions options(const Scene& scene) {
        WhittedOptions opt;
        opt.maxDepth = scene.settings.maxDepth;
        opt.ambient = whittedAmbient(scene.settings);
        return opt;
    }

    // The scene's options, read once per render (not per camera ray: the ambient term is a
    // render parameter, looked up by name).
    void prepare(const Scene& scene) override { options_ = options(scene); }

    Color Li(const Scene& scene, const Ray& ray, Rng&) const override { return LiWhitted(scene, ray, 0, options_); }

    WhittedOptions options_;
};

// L [DG] S* E from point lights, L S* E from every light (whitted.h); with area lights or a
// background, which it shows but lights no surface with, or with an ambient term, no expression
// says which paths it carries.
std::string whittedPaths(const Scene& scene) {
    if (scene.caps.areaLights || scene.caps.backgroundLight || !isBlack(whittedAmbient(scene.settings))) return "";
    return "L[DG]S*E|LS*E";
}
[[maybe_unused]] const bool carried = Registry<CarriedPaths>::add("whitted", whittedPaths);

}  // namespace

PS_REGISTER_INTEGRATOR(Whitted, "whitted",
                       "Whitted ray tracing: mirrors and both branches of glass, point lights with shadow rays, "
                       "an ambient term (lesson 11)");

}  // namespace ps
