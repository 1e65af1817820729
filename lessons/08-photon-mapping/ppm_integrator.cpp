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
// traced per pass: four per pixel, at least kMinPhotons.
constexpr float kInitialRadius = 0.03f;
constexpr int kMinPhotons = 8192;
constexpr uint64_t kPpmSalt = 0x6A09E667F3BCC909ull;
int photonsPerPass(const Image& out) { return std::max(kMinPhotons, 4 * out.width * out.height); }

}  // namespace

void renderPpmPass(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out, SampleStats& stats,
                   const PhotonRules& rules) {
    const double r1 = double(kInitialRadius) * scene.radius;
    const float r2 = float(ppmRadius2(r1 * r1, int(iteration) + 1));
    const int maxDepth = scene.settings.maxDepth;
    const PhotonMap map =
        tracePhotonMap(scene, MapKind::Global, photonsPerPass(out), maxDepth, seed ^ kPpmSalt, iteration, stats, rules);
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
