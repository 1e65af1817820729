// Lesson 5 — one light path, connected to the camera at every vertex. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

void traceLightPath(const Scene& scene, Rng& rng, int maxDepth, const SplatTarget& out) {
    //! TODO(05) The light path (Eq. 5.1-5.4):
    //!          1. start = startLightPath(scene, rng.uniform(), rng.uniform2(), rng.uniform2());
    //!             stop if it is not valid.
    //!          2. 0 bounces, the light seen directly: unless the light is the background,
    //!             c = connectToCamera(scene, start.y0, onSurface = the light is not a point
    //!             light); if valid, add Le / start.pdfA * c.importance at c.raster, where Le is
    //!             the light's intensity (point light) or emittedRadiance(light, y0.n, c.wCam).
    //!          3. beta = start.beta, ray = start.ray, throughput = 1 (the product of the
    //!             weights since the light, for Russian roulette); for bounces = 1, 2, ...,
    //!             maxDepth:
    //!             a. scene.intersect(ray, sp), stop on a miss; wLight = -ray.d.
    //!             b. Unless the material is delta: c = connectToCamera(scene, sp, true); if
    //!                valid, add beta * evalBSDF(m, sp.n, c.wCam, wLight) * c.importance.
    //!             c. Stop if bounces == maxDepth.
    //!             d. sampleAdjointBSDF(m, sp.n, wLight, rng.uniform2(), rng.uniform(), s),
    //!                stop if false; beta and throughput *= s.weight; stop if beta is black.
    //!             e. Russian roulette: q = survivalProbability(throughput, bounces); if q < 1,
    //!                stop if rng.uniform() >= q, else divide beta and throughput by q.
    //!             f. ray = scene.spawnRay(sp, s.wi).
    //! STUB (void)scene; (void)rng; (void)maxDepth; (void)out;
    //! STUB (void)PS_TODO("lesson 05: traceLightPath", 0);
    //! BEGIN
    const LightPathStart start = startLightPath(scene, rng.uniform(), rng.uniform2(), rng.uniform2());
    if (!start.valid) return;
    const Light& light = scene.lights[start.light];
    // 0 bounces: the point on the light seen directly (not the background: no point to connect).
    if (!light.isInfinite()) {
        const CameraConnection c = connectToCamera(scene, start.y0, !light.isDelta());
        if (c.valid) {
            const Color Le = light.isDelta() ? light.Le : emittedRadiance(light, start.y0.n, c.wCam);
            out.add(c.raster, Le * (c.importance / start.pdfA));
        }
    }
    Color beta = start.beta, throughput(1.0f);
    Ray ray = start.ray;
    for (int bounces = 1; bounces <= maxDepth; ++bounces) {
        SurfacePoint sp;
        if (!scene.intersect(ray, sp)) break;
        const Vec3 wLight = -ray.d;
        const Material& m = scene.materials[sp.material];
        if (!m.isDelta()) {
            const CameraConnection c = connectToCamera(scene, sp, true);
            if (c.valid) out.add(c.raster, beta * evalBSDF(m, sp.n, c.wCam, wLight) * c.importance);
        }
        if (bounces == maxDepth) break;
        BSDFSample s;
        if (!sampleAdjointBSDF(m, sp.n, wLight, rng.uniform2(), rng.uniform(), s)) break;
        beta *= s.weight;
        throughput *= s.weight;
        if (isBlack(beta)) break;
        const float q = survivalProbability(throughput, bounces);
        if (q < 1.0f) {
            if (rng.uniform() >= q) break;
            beta /= q;
            throughput /= q;
        }
        ray = scene.spawnRay(sp, s.wi);
    }
    //! END
}

}  // namespace ps
