#include "integrator.h"
#include "errors.h"
#include "eyelight.h"

namespace ps {

void PixelIntegrator::renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                                      SampleStats& stats) {
    const int w = out.width, h = out.height;
    uint64_t nan = 0, inf = 0, rays = 0;
#pragma omp parallel reduction(+ : nan, inf, rays)
    {
        SampleStats local;
#pragma omp for schedule(dynamic, 64)
        for (int pixel = 0; pixel < w * h; ++pixel) {
            // The pixel's random numbers depend on (seed, iteration, pixel) only.
            Rng rng = taskRng(seed, iteration, static_cast<uint32_t>(pixel));
            const Vec2 raster(static_cast<float>(pixel % w) + rng.uniform(),
                              static_cast<float>(pixel / w) + rng.uniform());
            out.pixels[pixel] = checkSample(Li(scene, scene.camera.generateRay(raster), rng), local);
        }
        nan += local.nan;
        inf += local.inf;
        rays += takeRayCount();
    }
    stats.nan += nan;
    stats.inf += inf;
    stats.rays += rays;
}

std::vector<IntegratorInfo> integratorList() {
    return {
        {"eyelight", "albedo times |cos| between the surface normal and the eye ray at the first hit"},
        {"normals", "the surface normal at the first hit, mapped to colours (n + 1) / 2"},
    };
}

std::unique_ptr<Integrator> makeIntegrator(const std::string& name) {
    if (name == "eyelight") return std::make_unique<EyeLight>();
    if (name == "normals") return std::make_unique<NormalView>();
    std::string known;
    for (const auto& i : integratorList()) known += (known.empty() ? "" : ", ") + i.name;
    throw InputError("unknown algorithm '" + name + "' (known: " + known + ")");
}

}  // namespace ps
