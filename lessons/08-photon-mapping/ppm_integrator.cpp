// Lesson 8 — progressive photon mapping, the render command's `ppm` (plumbing: read it, nothing to
// write here). Knaus and Zwicker's form: pass i (iteration i - 1) traces a new global map and
// renders one camera ray per pixel with a fixed-radius estimate of radius r_i (LiProgressive,
// Eq. 8.14), and the film averages the passes, as it does for every progressive integrator. The
// radius of pass i depends on i alone (Eq. 8.13, ppmRadius2), so a pass keeps no state from the
// earlier ones: renderIteration is a function of (scene, iteration, seed), and the image does not
// depend on the number of threads (the photon pass and the pixels run in the framework's task
// loop). README, section 1.9, says why this form and not Hachisuka and Jensen's per-pixel
// statistics.
#include <cmath>
#include <string>
#include "08-photon-mapping/photonmap.h"
#include "tasks.h"

namespace ps {

double ppmRadius2(double r1sq, int pass, double alpha) {
    double r2 = r1sq;
    for (int i = 1; i < pass; ++i) r2 = ppmNextRadius2(r2, i, alpha);
    return r2;
}

namespace {

// The first pass's radius, as a fraction of the scene's bounding radius, and the photon paths
// traced per pass: four per pixel, at least kMinPhotons. A scene may set both, and alpha, as
// render parameters (`render ppmradius R ppmphotons N ppmalpha A`, scenes/README.md): SmallVCM's
// scenes set SmallVCM's own, so that both renderers run the same algorithm (bench/README.md).
constexpr float kInitialRadius = 0.03f;
constexpr int kMinPhotons = 8192;
constexpr uint64_t kPpmSalt = 0x6A09E667F3BCC909ull;
int photonsPerPass(const Scene& scene, const Image& out) {
    const float n = renderParameter(scene.settings, "ppmphotons", 0.0f);
    return n > 0.0f ? int(n) : std::max(kMinPhotons, 4 * out.width * out.height);
}

[[maybe_unused]] const bool radiusRegistered = Registry<RenderParameter>::add(
    "ppmradius", {"ppm's first radius in scene units (default: 0.03 of the scene's bounding radius)", "R", 1,
                  [](const std::vector<float>& v) {
                      return v[0] > 0.0f ? std::string() : std::string("must be a positive number");
                  }});
[[maybe_unused]] const bool photonsRegistered = Registry<RenderParameter>::add(
    "ppmphotons",
    {"ppm's photon paths per pass (default: four per pixel, at least 8192)", "N", 1, [](const std::vector<float>& v) {
         return v[0] >= 1.0f && v[0] <= 1e9f && v[0] == std::floor(v[0])
                    ? std::string()
                    : std::string("must be a whole number of photon paths between 1 and 1e9");
     }});
[[maybe_unused]] const bool alphaRegistered = Registry<RenderParameter>::add(
    "ppmalpha", {"ppm's radius reduction alpha, Eq. 8.13 (default 2/3)", "A", 1, [](const std::vector<float>& v) {
                     return v[0] > 0.0f && v[0] < 1.0f ? std::string()
                                                       : std::string("must lie between 0 and 1 (exclusive)");
                 }});

}  // namespace

void renderPpmPass(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out, SampleStats& stats,
                   const PhotonRules& rules) {
    const RenderSettings& set = scene.settings;
    // The defaults in double, as before the scenes could set them (the stored renders' bytes).
    const float r1Set = renderParameter(set, "ppmradius", 0.0f), alphaSet = renderParameter(set, "ppmalpha", 0.0f);
    const double r1 = r1Set > 0.0f ? double(r1Set) : double(kInitialRadius) * scene.radius;
    const double alpha = alphaSet > 0.0f ? double(alphaSet) : kPpmAlpha;
    const float r2 = float(ppmRadius2(r1 * r1, int(iteration) + 1, alpha));
    const int maxDepth = set.maxDepth;
    const PhotonMap map = tracePhotonMap(scene, MapKind::Global, photonsPerPass(scene, out), maxDepth, seed ^ kPpmSalt,
                                         iteration, stats, rules);
    renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task&) {
        const Ray ray = cameraRay(scene.camera, jitteredRaster(pixel, out.width, rng), rng);
        return LiProgressive(scene, ray, rng, map, r2, maxDepth);
    });
}

namespace {

struct ProgressivePhotonMapper : Integrator {
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        renderPpmPass(scene, iteration, seed, out, stats);
    }
};

}  // namespace

PS_REGISTER_INTEGRATOR_CAPS(
    ProgressivePhotonMapper, "ppm",
    "progressive photon mapping: the radius shrinks from pass to pass (Knaus-Zwicker, lesson 8)",
    IntegratorCaps().withCameraModels());

}  // namespace ps
