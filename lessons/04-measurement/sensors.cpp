// Lesson 4 — plumbing for the sensors (read it, nothing to write here): the region S of a
// scene, the point a particle starts from, and the `measure` integrator, which renders every
// pixel as <W_e^(j), L> with directions drawn uniformly in a cone around the pixel (Eq. 4.7),
// so that it can be compared with `pt`, whose camera rays sample W_e^(j) cos exactly (Eq. 4.8).
#include <algorithm>
#include "04-measurement/measurement.h"
#include "errors.h"
#include "tasks.h"

namespace ps {

Region regionWithMaterial(const Scene& scene, const std::string& material) {
    int id = -1;
    for (size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].name == material) id = static_cast<int>(i);
    Region S;
    S.member.assign(scene.prims.size(), false);
    for (size_t i = 0; i < scene.prims.size(); ++i) {
        const Primitive& pr = scene.prims[i];
        if (id < 0 || pr.material != id) continue;
        S.member[i] = true;
        S.area += pr.shape == ShapeKind::Triangle ? scene.triangles[pr.index].area() : scene.spheres[pr.index].area();
    }
    if (S.area <= 0.0) throw InputError(scene.path, 0, "no surface with material '" + material + "' (the region S)");
    return S;
}

SurfacePoint emissionPoint(const Scene& scene, int l, const EmissionSample& e) {
    SurfacePoint sp;
    sp.p = e.p;
    sp.n = e.n;
    sp.light = l;
    // Area lights: offset rays by a few ulps of the point's coordinates, as for any surface
    // (the primitive is not known, so a ray may not skip it; the offset keeps it off).
    if (scene.lights[l].kind == LightKind::Area) sp.errScale = maxAbsComponent(e.p);
    return sp;
}

namespace {

// Directions uniform in the cone around the unit axis whose half-angle theta_max has
// 1 - cos(theta_max) = oneMinusCosMax (kept apart from cos: a pixel's cone is so narrow that
// cos(theta_max) rounds to a handful of floats below 1). Density 1 / (2 pi oneMinusCosMax).
Vec3 sampleCone(const Vec2& u, float oneMinusCosMax, const Vec3& axis) {
    const float oneMinusCos = u.x * oneMinusCosMax;
    const float sinTheta = std::sqrt(std::max(0.0f, oneMinusCos * (2.0f - oneMinusCos)));
    const float phi = 2.0f * kPi * u.y;
    return Frame(axis).toWorld(Vec3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), 1.0f - oneMinusCos));
}

struct Measure : Integrator {
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        const Camera& camera = scene.camera;
        renderPixelTasks(seed, iteration, out, stats, false, [&](int pixel, Rng& rng, Task&) {
            const int px = pixel % out.width, py = pixel / out.width;
            // The cone around the pixel's centre direction that holds its four corners, 1 %
            // wider: 1 - cos(angle between unit a and b) = |a - b|^2 / 2, without rounding.
            const Vec3 axis = camera.generateRay(Vec2(px + 0.5f, py + 0.5f)).d;
            float oneMinusCosMax = 0.0f;
            for (int c = 0; c < 4; ++c) {
                const Vec3 corner = camera.generateRay(Vec2(float(px + (c & 1)), float(py + (c >> 1)))).d;
                oneMinusCosMax = std::max(oneMinusCosMax, 0.5f * glm::dot(axis - corner, axis - corner));
            }
            oneMinusCosMax = std::min(2.0f, 1.02f * oneMinusCosMax);
            const float pdf = 1.0f / (2.0f * kPi * oneMinusCosMax);
            const Vec3 dir = sampleCone(rng.uniform2(), oneMinusCosMax, axis);
            return pixelMeasurementSample(scene, px, py, dir, pdf, rng, scene.settings.maxDepth);
        });
    }
};

}  // namespace

PS_REGISTER_INTEGRATOR(Measure, "measure",
                       "every pixel as <W_e, L>: directions uniform in a cone around the pixel, L from pt (lesson 4)");

}  // namespace ps
