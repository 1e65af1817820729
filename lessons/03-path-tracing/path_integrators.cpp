// Lesson 3 — the path tracers the render command knows (plumbing: read it, nothing to write
// here). Each runs one of the estimators of this lesson with the scene's maximum depth
// (scene.settings.maxDepth, `--maxdepth` on the command line; 0 = emission seen directly). All
// three are visitors of the one random walk, cameraWalk (walk.cpp, Eq. 3.3-3.5):
//
//   pt-bsdf   BSDF sampling only (random_walk.cpp, Eq. 3.3, 3.4)
//   pt-nee    with next-event estimation (next_event.cpp, Eq. 3.6)
//   pt        next-event estimation and BSDF hits combined by MIS (path_mis.cpp, Eq. 3.7)
//
// LiMIS's visitor, addMISContribution, adds your two halves of Eq. 3.7 (path_mis.cpp) in order.
#include "03-path-tracing/pathtracer.h"

namespace ps {

void addMISContribution(const Scene& scene, const WalkVertex& v, Rng& rng, int maxDepth, Color& L) {
    L += misEmission(scene, v);
    L += misLightSample(scene, v, rng, maxDepth);
}

float pdfWalk(const Scene& scene, const WalkVertex& v, const DirectSample& d) {
    if (d.delta || !v.sampler) return d.pdfBSDF;
    return pdfWalk(scene, v, d.wi);
}

namespace {

struct PathBSDF : PixelIntegrator {
    Color Li(const Scene& scene, const Ray& ray, Rng& rng) const override {
        return LiRandomWalk(scene, ray, rng, scene.settings.maxDepth);
    }
};

struct PathNEE : PixelIntegrator {
    Color Li(const Scene& scene, const Ray& ray, Rng& rng) const override {
        return LiNextEvent(scene, ray, rng, scene.settings.maxDepth);
    }
};

struct PathMIS : PixelIntegrator {
    Color Li(const Scene& scene, const Ray& ray, Rng& rng) const override {
        return LiMIS(scene, ray, rng, scene.settings.maxDepth);
    }
};

}  // namespace

PS_REGISTER_INTEGRATOR(PathBSDF, "pt-bsdf", "path tracing, BSDF sampling only: the random walk (lesson 3)");
PS_REGISTER_INTEGRATOR(PathNEE, "pt-nee", "path tracing with next-event estimation (lesson 3)");
PS_REGISTER_INTEGRATOR(PathMIS, "pt", "path tracing, next-event estimation and BSDF hits combined by MIS (lesson 3)");

}  // namespace ps
