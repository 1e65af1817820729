// Lesson 8 — filling the irradiance cache for one image (plumbing: read it, nothing to write here).
// Ward fills the cache lazily, as the pixels are rendered: the first point no record covers gets
// one, and every later point may use it. That order depends on which thread renders which pixel
// first, so here the cache is filled before the pixels are rendered, coarse to fine: the points
// seen through the centres of every s-th pixel in both directions first (s the largest power of 2
// up to a quarter of the image's larger side: 4 x 4 points or so), then every s/2-th, and so on
// to every pixel. Within one level the candidates are tested against the records of the earlier
// levels only, in parallel tasks (framework/tasks.h: candidate i of a level draws from its own
// generator), and the new records are appended in pixel order after the level: the cache, and so
// the image, do not depend on the number of threads. Two candidates of one level may both make a
// record where one would have done (they are s pixels apart); the coarser levels make that rare.
#include <optional>
#include "08-photon-mapping/photonmap.h"
#include "tasks.h"

namespace ps {

namespace {
constexpr uint64_t kCacheSalt = 0xBB67AE8584CAA73Bull;
}  // namespace

IrradianceCache buildIrradianceCache(const Scene& scene, const PhotonMap& global, const PmOptions& opt, float a,
                                     int width, int height, uint64_t seed, uint32_t iteration, SampleStats& stats) {
    IrradianceCache cache;
    cache.a = a;
    int coarsest = 1;
    while (4 * coarsest * 2 <= std::max(width, height)) coarsest *= 2;
    for (int stride = coarsest; stride >= 1; stride /= 2) {
        // This level's candidates: pixels on the grid of `stride` and not on the coarser one.
        std::vector<int> pixels;
        for (int y = 0; y < height; y += stride)
            for (int x = 0; x < width; x += stride)
                if (stride == coarsest || x % (2 * stride) != 0 || y % (2 * stride) != 0)
                    pixels.push_back(y * width + x);
        std::vector<std::optional<IrradianceRecord>> made(pixels.size());
        const uint64_t levelSeed = seed ^ (kCacheSalt + uint64_t(stride) * 0x9E3779B97F4A7C15ull);
        runTasks(TaskLoop(int(pixels.size()), levelSeed, iteration), stats, [&](int item, Rng& rng, Task&) {
            const int pixel = pixels[size_t(item)];
            const Ray ray = scene.camera.generateRay(Vec2(float(pixel % width) + 0.5f, float(pixel / width) + 0.5f));
            cameraWalk(scene, ray, rng, {opt.maxDepth}, [&](const WalkVertex& v) {
                if (!v.hit) return false;
                const Material& m = scene.materials[size_t(v.sp.material)];
                if (m.isDelta()) return true;  // through mirrors and glass to the first other surface
                if (m.kind != BSDFKind::Diffuse || v.bounces >= opt.maxDepth) return false;
                const Vec3 n = glm::dot(v.sp.n, v.wo) < 0.0f ? -v.sp.n : v.sp.n;
                Color E;
                if (!interpolateIrradiance(cache, v.sp.p, n, E))
                    made[size_t(item)] = irradianceRecord(scene, v.sp, v.wo, v.bounces, rng, global, opt);
                return false;
            });
        });
        for (const std::optional<IrradianceRecord>& r : made)
            if (r) cache.records.push_back(*r);
    }
    return cache;
}

}  // namespace ps
