// Lesson 5 — the light tracer the render command knows as `lt` (plumbing: read it, nothing to
// write here). One iteration traces N = width * height light paths (as many as a path tracer's
// camera rays) in fixed batches; each batch has its own list in a SplatBuffer, and the lists
// are added in batch order, so the image does not depend on the number of threads. Every
// splat carries the factor 1/N of Eq. 5.4. The random numbers of path i of iteration k come
// from taskRng(seed, k, i), whichever thread traces it (the framework's task loop,
// framework/tasks.h).
//
// Left out where the scene shows it cannot contribute (exact: the image's expectation is the
// same): in a scene whose surfaces are all specular (or black) no vertex after the light can be
// connected to the pinhole (Eq. 5.9), so the paths end at the light (maxDepth 0).
#include "05-light-tracing/lighttracer.h"
#include "tasks.h"

namespace ps {

CameraConnection connectToCamera(const Scene& scene, const SurfacePoint& y, bool onSurface) {
    return connectToCamera(scene, y, onSurface, scene.camera.position());
}

void traceLightPath(const Scene& scene, Rng& rng, int maxDepth, const SplatTarget& out) {
    traceLightPath(scene, rng, WalkOptions(maxDepth), out);
}

namespace {

struct LightTracer : Integrator {
    // True if no surface can send light towards the camera: every material is specular, or
    // black (a light's own "(emitter)" material).
    static bool onlyLightVertices(const Scene& scene) {
        if (!scene.settings.prune) return false;
        for (const Material& m : scene.materials)
            if (!m.isDelta() && !isBlack(m.albedo)) return false;
        return true;
    }

    std::vector<std::string> leftOut(const Scene& scene) const override {
        if (!onlyLightVertices(scene)) return {};
        return {
            "light paths beyond the lights: every surface is specular or black, so no later vertex can be "
            "connected to the pinhole (lesson 5, Eq. 5.9)"};
    }

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        const int maxDepth = onlyLightVertices(scene) ? 0 : scene.settings.maxDepth;
        renderLightPathTasks(seed, iteration, out, stats,
                             [&](int, Rng& rng, Task& task) { traceLightPath(scene, rng, maxDepth, task.splat); });
    }
};

}  // namespace

// A camera model: traceLightPath connects each path to one of the camera's points.
PS_REGISTER_INTEGRATOR_CAPS(LightTracer, "lt",
                            "light tracing: paths from the lights, every vertex connected to the camera (lesson 5)",
                            IntegratorCaps().withCameraModels());

}  // namespace ps
