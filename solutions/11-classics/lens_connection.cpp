// Lesson 11 — bidirectional path tracing's technique t = 0: a light subpath that hits the lens.
// Interface: lessons/11-classics/thinlens.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/thinlens.h"
#include "todo.h"

namespace ps {

LensConnection connectLens(const Scene& scene, const PathVertex* y, int m, Rng& rng) {
    //! TODO(11) Eq. 11.16, 11.17: one more step of the light walk from y_m, and the lens point it meets.
    //!          1. The ray and beta': m = 0: start = startLightPath(scene, uLight, uPos, uDir)
    //!             (rng.uniform(), rng.uniform2(), rng.uniform2(), drawn into variables in that
    //!             order; invalid if not valid); the ray is start.ray,
    //!             beta' = start.beta, and c.light the new y_0: its sp is start.y0, onLight,
    //!             pointLight and infinite from its light, an infinite one's sp.n = -start.ray.d.
    //!             m >= 1: sampleAdjointBSDF(y_m's material, y_m.sp.n, direction(y_m, y_{m-1}),
    //!             u, uLobe, b) (rng.uniform2(), then rng.uniform(); invalid if it fails); the ray is
    //!             scene.spawnRay(y_m.sp, b.wi), beta' = y_m.beta * b.weight.
    //!          2. camera.hit(ray, t, z): invalid if it misses; then scene.occluded on the ray
    //!             cut at t (ray.tMax = t): invalid if blocked.
    //!          3. W = width * height * camera.We(z, -ray.d); invalid if 0. value = beta' W,
    //!             raster = camera.rasterOfDirection(z, -ray.d), lens = cameraVertex(scene, z).
    //!          Pitfalls: the numbers drawn in this order; a specular y_m is fine (t = 0 needs no
    //!          connection at it); no cosine or 1 / d^2 in value: the step's density cancels them.
    //! STUB (void)scene; (void)y; (void)m; (void)rng;
    //! STUB return PS_TODO("lesson 11: connectLens", LensConnection());
    //! BEGIN
    LensConnection c;
    const Camera& camera = scene.camera;
    if (camera.isPinhole()) return c;
    Ray ray;
    Color beta;
    if (m == 0) {
        // Named, in this order: C++ evaluates a call's arguments in no fixed order.
        const float uLight = rng.uniform();
        const Vec2 uPos = rng.uniform2();
        const Vec2 uDir = rng.uniform2();
        const LightPathStart start = startLightPath(scene, uLight, uPos, uDir);
        if (!start.valid) return c;
        const Light& light = scene.lights[size_t(start.light)];
        c.light.sp = start.y0;
        c.light.onLight = true;
        c.light.pointLight = light.isDelta();
        c.light.infinite = light.isInfinite();
        if (c.light.infinite) c.light.sp.n = -start.ray.d;
        ray = start.ray;
        beta = start.beta;
    } else {
        const PathVertex& v = y[m];
        // Named, in this order: C++ evaluates a call's arguments in no fixed order.
        const Vec2 u = rng.uniform2();
        const float uLobe = rng.uniform();
        BSDFSample b;
        if (!sampleAdjointBSDF(scene.materials[size_t(v.sp.material)], v.sp.n, direction(v, y[m - 1]), u, uLobe, b))
            return c;
        ray = scene.spawnRay(v.sp, b.wi);
        beta = v.beta * b.weight;
    }
    float t = 0.0f;
    Vec3 z;
    if (!camera.hit(ray, t, z)) return c;
    Ray shadow = ray;
    shadow.tMax = t;
    if (scene.occluded(shadow)) return c;
    const float W = float(camera.width()) * float(camera.height()) * camera.We(z, -ray.d);
    if (!(W > 0.0f) || !camera.rasterOfDirection(z, -ray.d, c.raster)) return c;
    c.value = beta * W;
    c.lens = cameraVertex(scene, z);
    c.valid = !isBlack(c.value);
    return c;
    //! END
}

}  // namespace ps
