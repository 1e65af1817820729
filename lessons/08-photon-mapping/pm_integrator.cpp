// Lesson 8 — the photon mappers the render command knows as `pm` and `pm-ic` (plumbing: read it,
// nothing to write here). Every iteration traces a new global map (photonsPerMap: as many photon
// paths as pixels, at least kMinPhotons) and, when the scene has a specular surface, a new caustic
// map (as many), with seeds of their own derived from the render's seed and the iteration
// (tracePhotonMap: the framework's task loop, so the maps do not depend on the number of
// threads), then one camera ray through a jittered point of every pixel, estimated by
// LiPhotonMap (Eq. 8.11). The iterations are independent estimates with the same bias: averaging
// them removes the noise, not the bias (README, "Bias"). `pm-ic` also fills an irradiance cache
// from the iteration's global map before the pixels (Eq. 8.15-8.18).
//
// Left out where the scene shows it cannot contribute (exact): without a specular surface there
// is no L S+ D path, so no caustic map is traced.
#include "08-photon-mapping/photonmap.h"
#include "tasks.h"

namespace ps {

// Photon paths emitted per iteration for each map: as many as the image has pixels (as lesson 5's
// light tracer traces light paths), at least kMinPhotons.
constexpr int kMinPhotons = 8192;
int photonsPerMap(const Image& out) { return std::max(kMinPhotons, out.width * out.height); }

uint64_t photonSeed(uint64_t seed, MapKind kind) {
    constexpr uint64_t kGlobalSalt = 0x8A1F0C3D5B7E9246ull, kCausticSalt = 0x3C6EF372FE94F82Bull;
    return seed ^ (kind == MapKind::Global ? kGlobalSalt : kCausticSalt);
}

PmOptions pmOptions(const Scene& scene) {
    PmOptions opt;
    opt.maxDepth = scene.settings.maxDepth;
    opt.globalEstimate.filter = Filter::Box;
    opt.globalEstimate.k = 50;
    opt.globalEstimate.maxRadius = 0.1f * scene.radius;
    opt.causticEstimate.filter = Filter::Cone;
    opt.causticEstimate.k = 50;
    opt.causticEstimate.maxRadius = 0.02f * scene.radius;
    return opt;
}

namespace {

constexpr uint64_t kCacheSalt = 0xA54FF53A5F1D36F1ull;

bool needsCausticMap(const Scene& scene) { return !scene.settings.prune || scene.caps.hasDeltaBSDF(); }

struct PhotonMapper : Integrator {
    std::vector<std::string> leftOut(const Scene& scene) const override {
        if (needsCausticMap(scene)) return {};
        return {"the caustic map: no specular surface, so no photon path L S+ D (lesson 8, Eq. 8.2)"};
    }

    static PhotonMaps traceMaps(const Scene& scene, uint32_t iteration, uint64_t seed, const Image& out,
                                const PmOptions& opt, SampleStats& stats) {
        PhotonMaps maps;
        maps.global = tracePhotonMap(scene, MapKind::Global, photonsPerMap(out), opt.maxDepth,
                                     photonSeed(seed, MapKind::Global), iteration, stats);
        if (needsCausticMap(scene))
            maps.caustic = tracePhotonMap(scene, MapKind::Caustic, photonsPerMap(out), opt.maxDepth,
                                          photonSeed(seed, MapKind::Caustic), iteration, stats);
        return maps;
    }

    static void renderPixels(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out, const PhotonMaps& maps,
                             const PmOptions& opt, SampleStats& stats) {
        renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task&) {
            const Ray ray = cameraRay(scene.camera, jitteredRaster(pixel, out.width, rng), rng);
            return LiPhotonMap(scene, ray, rng, maps, opt);
        });
    }

    // A camera model: the camera rays come from it (tasks.h, cameraRay); the photon maps do not
    // depend on the camera. (pm-ic's cache is filled from the pinhole's rays through the pixel
    // centres; where a camera ray's point has no record it gathers as pm.)

    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        const PmOptions opt = pmOptions(scene);
        const PhotonMaps maps = traceMaps(scene, iteration, seed, out, opt, stats);
        renderPixels(scene, iteration, seed, out, maps, opt, stats);
    }
};

// `pm-ic`: pm with Ward's irradiance cache as the final gather at Lambertian surfaces (Eq. 8.15-8.18).
// Every iteration fills a new cache from its own global map before the pixels are rendered
// (buildIrradianceCache: coarse to fine, in a fixed order); a point no record covers falls back to
// pm's one-ray final gathering.
struct PhotonMapperCached : PhotonMapper {
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        PmOptions opt = pmOptions(scene);
        opt.minR = kCacheMinR * scene.radius;
        opt.maxR = kCacheMaxR * scene.radius;
        PhotonMaps maps = traceMaps(scene, iteration, seed, out, opt, stats);
        const IrradianceCache cache = buildIrradianceCache(scene, maps.global, opt, kCacheErrorBound, out.width,
                                                           out.height, seed ^ kCacheSalt, iteration, stats);
        opt.cache = &cache;
        renderPixels(scene, iteration, seed, out, maps, opt, stats);
    }
};

}  // namespace

PS_REGISTER_INTEGRATOR_CAPS(PhotonMapper, "pm",
                            "photon mapping: direct light, caustic map, final gathering into the global map (lesson 8)",
                            IntegratorCaps().withCameraModels());
PS_REGISTER_INTEGRATOR_CAPS(PhotonMapperCached, "pm-ic",
                            "pm with Ward's irradiance cache as the final gather at diffuse surfaces (lesson 8)",
                            IntegratorCaps().withCameraModels());

}  // namespace ps
