// Lesson 11 — distributed ray tracing, the algorithm the render command knows as `drt` (plumbing:
// read it, nothing to write here). One iteration: one camera ray per pixel through a jittered
// point of the pixel and, for a thin-lens camera, a point of the lens (the framework's pixel
// loop: PixelIntegrator, tasks.h's cameraRay), whose radiance LiDistributed estimates.
#include "11-classics/distributed.h"
#include "11-classics/path_filter.h"

namespace ps {

namespace {

struct DistributedRayTracer : PixelIntegrator {
    Color Li(const Scene& scene, const Ray& ray, Rng& rng) const override {
        return LiDistributed(scene, ray, rng, scene.settings.maxDepth);
    }
};

// The paths it carries (Eq. 11.19): pt filtered to them is its reference (the extreme tests,
// lesson 11's graded test). Not where a Phong material has exponent 0: Heckbert's D (its BRDF is
// albedo / pi, Eq. 11.1), but LiDistributed ends the path only at BSDFKind::Diffuse and goes on
// through it as through a glossy surface, so no expression over L, D, G, S, E says which paths it
// carries there.
std::string distributedPaths(const Scene& scene) {
    for (const Material& m : scene.materials)
        if (m.kind == BSDFKind::Phong && m.exponent == 0.0f) return "";
    return kDistributedPaths;
}
[[maybe_unused]] const bool carried = Registry<CarriedPaths>::add("drt", distributedPaths);

}  // namespace

PS_REGISTER_INTEGRATOR(DistributedRayTracer, "drt",
                       "distributed ray tracing: lens, area lights and glossy lobes sampled, mirror and glass "
                       "followed, no diffuse interreflection: paths L D? (G|S)* E (lesson 11)");

}  // namespace ps
