#include "eyelight.h"

namespace ps {

Color EyeLight::Li(const Scene& scene, const Ray& ray, Rng&) const {
    Ray r = ray;
    SurfacePoint sp;
    if (!scene.intersect(r, sp)) return scene.backgroundRadiance();
    if (sp.light >= 0) {
        const Color Le = emittedRadiance(scene.lights[sp.light], sp.n, -ray.d);
        if (!isBlack(Le)) return Le;
    }
    const Material& m = scene.materials[sp.material];
    const Color reflectance = m.kind == BSDFKind::Dielectric ? Color(1.0f) : m.albedo;
    return reflectance * std::abs(glm::dot(sp.n, ray.d));
}

Color NormalView::Li(const Scene& scene, const Ray& ray, Rng&) const {
    Ray r = ray;
    SurfacePoint sp;
    if (!scene.intersect(r, sp)) return Color(0.0f);
    return 0.5f * (sp.n + Vec3(1.0f));
}

}  // namespace ps
