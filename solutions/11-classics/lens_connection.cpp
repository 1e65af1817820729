// Lesson 11 — bidirectional path tracing's technique t = 0: a light subpath that hits the lens.
// Interface: lessons/11-classics/thinlens.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/thinlens.h"
#include "todo.h"

namespace ps {

LensConnection connectLens(const Scene& scene, const PathVertex* y, int m, Rng& rng) {
    //! TODO(11) The technique t = 0 at y_m (Eq. 11.16, 11.17), as connectLens and LensConnection in thinlens.h state
    //!          it, with the numbers drawn in the order stated there (the tests replay them). Pitfalls (README 6): no
    //!          cosine or 1 / d^2 in the value; only what lies between y_m and the lens blocks it; a specular y_m is
    //!          fine.
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
