// Lesson 6 — plumbing (nothing to write here): the image of one technique (s, t) for paths of
// length exactly k (Eq. 6.2 with one technique): every iteration samples N = width * height
// paths with sampleTechnique and adds f / (p N) at the pixel each lands in, through a
// SplatBuffer as lesson 5 (fixed batches, added in order: the image does not depend on the
// number of threads). The render command knows path-s0 ... path-s4 (s fixed) and path-t1
// (s = k, light tracing), with k = maxdepth + 1.
#include "06-path-space/paths.h"
#include "tasks.h"

namespace ps {

namespace {

struct TechniqueIntegrator : Integrator {
    int k, s;  // k < 0: maxdepth + 1; s < 0: s = k (t = 1)
    TechniqueIntegrator(int k_, int s_) : k(k_), s(s_) {}

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        const int length = k >= 0 ? k : scene.settings.maxDepth + 1;
        const int lightVertices = s >= 0 ? s : length;
        renderLightPathTasks(seed, iteration, out, stats, [&](int, Rng& rng, Task& task) {
            const TechniqueSample ts = sampleTechnique(scene, length, lightVertices, rng);
            if (!ts.valid) return;
            const Color c = techniqueEstimate(scene, ts, lightVertices);
            if (!isBlack(c)) task.splat.add(ts.raster, c);
        });
    }
};

template <int S>
struct FixedS : TechniqueIntegrator {
    FixedS() : TechniqueIntegrator(-1, S) {}
};
using PathS0 = FixedS<0>;
using PathS1 = FixedS<1>;
using PathS2 = FixedS<2>;
using PathS3 = FixedS<3>;
using PathS4 = FixedS<4>;
using PathT1 = FixedS<-1>;

}  // namespace

PS_REGISTER_INTEGRATOR_CAPS(
    PathS0, "path-s0", "paths of length maxdepth + 1 by technique s = 0 alone: camera subpath hits a light (lesson 6)",
    IntegratorCaps().withCameraModels());
PS_REGISTER_INTEGRATOR_CAPS(PathS1, "path-s1",
                            "paths of length maxdepth + 1 by technique s = 1 alone: next-event estimation (lesson 6)",
                            IntegratorCaps().withCameraModels());
PS_REGISTER_INTEGRATOR_CAPS(PathS2, "path-s2", "paths of length maxdepth + 1 by technique s = 2 alone (lesson 6)",
                            IntegratorCaps().withCameraModels());
PS_REGISTER_INTEGRATOR_CAPS(PathS3, "path-s3", "paths of length maxdepth + 1 by technique s = 3 alone (lesson 6)",
                            IntegratorCaps().withCameraModels());
PS_REGISTER_INTEGRATOR_CAPS(PathS4, "path-s4", "paths of length maxdepth + 1 by technique s = 4 alone (lesson 6)",
                            IntegratorCaps().withCameraModels());
PS_REGISTER_INTEGRATOR_CAPS(PathT1, "path-t1",
                            "paths of length maxdepth + 1 by technique t = 1 alone: light tracing (lesson 6)",
                            IntegratorCaps().withCameraModels());

RenderResult renderTechnique(const Scene& scene, int k, int s, int iterations, uint64_t seed, int threads) {
    TechniqueIntegrator integrator(k, s);
    RenderOptions opt;
    opt.spp = iterations;
    opt.seed = seed;
    opt.threads = threads;
    return render(scene, integrator, opt);
}

}  // namespace ps
