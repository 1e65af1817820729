// Lesson 6 — plumbing (nothing to write here): sampling a path of length k with technique
// (s, t = k + 1 - s) (Eq. 6.8; t = 0 only with a camera model, framework/camera.h), and the estimate f(x) / p_{s,t}(x) of one such path (Eq. 6.2),
// which uses your contribution and pdfTechnique. Interface: lessons/06-path-space/paths.h.
#include "06-path-space/paths.h"

namespace ps {

TechniqueSample sampleTechnique(const Scene& scene, int k, int s, Rng& rng) {
    TechniqueSample ts;
    const int t = k + 1 - s;
    const Camera& camera = scene.camera;
    if (k < 1 || s < 0 || t < 0) return ts;
    if (t == 0 && camera.isPinhole()) return ts;  // a ray cannot hit the pinhole (a camera model it can)
    Path& x = ts.x;
    x.resize(size_t(k) + 1);
    // The light subpath x0 ... x_{s-1}: a light chosen by power, a point and a direction on it,
    // then the BSDF in Importance mode (the light tracer's directions, lesson 5).
    if (s >= 1) {
        float P = 0.0f;
        const int l = scene.selectLight(rng.uniform(), P);
        if (l < 0 || P <= 0.0f) return ts;
        // Named, in this order: C++ evaluates a call's arguments in no fixed order.
        const Vec2 uPoint = rng.uniform2();
        const Vec2 uDirection = rng.uniform2();
        const EmissionSample e = sampleEmission(scene, l, uPoint, uDirection);
        if (!(e.pdfA > 0.0f && e.pdfW > 0.0f)) return ts;
        x[0] = lightVertex(scene, l, e);
        Ray ray = x[0].infinite ? Ray(e.p, e.dir) : scene.spawnRay(x[0].sp, e.dir);
        // t = 0: the light subpath's last vertex x_k is where its last ray meets the camera.
        const int surfaces = t == 0 ? s - 2 : s - 1;
        for (int i = 1; i <= surfaces; ++i) {
            SurfacePoint sp;
            if (!scene.intersect(ray, sp)) return ts;
            x[size_t(i)] = surfaceVertex(scene, sp);
            if (i == s - 1) break;
            // Named, in this order: C++ evaluates a call's arguments in no fixed order.
            const Vec2 u = rng.uniform2();  // in this order, as uPos and uDir above
            const float uLobe = rng.uniform();
            BSDFSample b;
            if (!sampleBSDF(scene.materials[size_t(sp.material)], sp.n, -ray.d, u, uLobe, Transport::Importance, b))
                return ts;
            ray = scene.spawnRay(sp, b.wi);
        }
        if (t == 0) {  // visibility up to the camera is f's (visible())
            float tz = 0.0f;
            Vec3 z;
            if (!camera.hit(ray, tz, z) || !camera.rasterOfDirection(z, -ray.d, ts.raster)) return ts;
            x[size_t(k)] = cameraVertex(scene, z);
            ts.valid = true;
            return ts;
        }
    }
    // The camera subpath x_k ... x_s: the camera point (the pinhole, or a camera model's point), a
    // ray through a uniform raster position, then the BSDF in Radiance mode (the path tracer's
    // directions, lesson 3).
    x[size_t(k)] = cameraVertex(scene, camera.samplePoint(rng));
    if (t >= 2) {
        // Named, in this order: C++ evaluates a call's arguments in no fixed order.
        const float ux = rng.uniform();  // in this order, as uPos and uDir above
        const float uy = rng.uniform();
        ts.raster = Vec2(ux * float(camera.width()), uy * float(camera.height()));
        Ray ray = camera.generateRay(ts.raster, x[size_t(k)].p());
        for (int j = k - 1; j >= s; --j) {
            SurfacePoint sp;
            if (!scene.intersect(ray, sp)) {
                if (j != 0 || scene.background < 0) return ts;  // only x0 may be the background
                x[0] = backgroundVertex(scene, ray.d);
                break;
            }
            x[size_t(j)] = surfaceVertex(scene, sp);
            if (j == s) break;
            // Named, in this order: C++ evaluates a call's arguments in no fixed order.
            const Vec2 u = rng.uniform2();  // in this order, as uPos and uDir above
            const float uLobe = rng.uniform();
            BSDFSample b;
            if (!sampleBSDF(scene.materials[size_t(sp.material)], sp.n, -ray.d, u, uLobe, Transport::Radiance, b))
                return ts;
            ray = scene.spawnRay(sp, b.wi);
        }
        if (s == 0 && !x[0].onLight) return ts;  // the camera subpath must end on a light
    } else {
        // t = 1: the pixel is where x_{k-1} projects (lesson 5's splat).
        if (x[size_t(k) - 1].infinite || !camera.rasterPosition(x[size_t(k)].p(), x[size_t(k) - 1].sp.p, ts.raster))
            return ts;
    }
    ts.valid = true;
    return ts;
}

Color techniqueEstimate(const Scene& scene, const TechniqueSample& ts, int s) {
    if (!ts.valid) return Color(0.0f);
    const double p = pdfTechnique(scene, ts.x, s);
    if (!(p > 0.0)) return Color(0.0f);
    const DColor f = contribution(scene, ts.x);
    if (f == DColor(0.0)) return Color(0.0f);
    return Color(f / p);
}

}  // namespace ps
