// Lesson 11 — Whitted's lights: every point light, through one shadow ray each. Interface:
// lessons/11-classics/whitted.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/whitted.h"
#include "todo.h"

namespace ps {

Color whittedDirect(const Scene& scene, const SurfacePoint& sp, const Vec3& wo) {
    //! TODO(11) The light of the point lights at sp towards wo (Eq. 11.7; whitted.h). Pitfalls (README 6): the cosine
    //!          at the surface and 1/d^2; the shadow ray ends at the light. Skip a light at distance 0.
    //! STUB (void)scene; (void)sp; (void)wo;
    //! STUB return PS_TODO("lesson 11: whittedDirect", Color(0.0f));
    //! BEGIN
    Color L(0.0f);
    const Material& m = scene.materials[size_t(sp.material)];
    for (const Light& light : scene.lights) {
        if (light.kind != LightKind::Point) continue;
        const Vec3 toLight = light.position - sp.p;
        const float d2 = glm::dot(toLight, toLight);
        if (!(d2 > 0.0f)) continue;
        const Vec3 w = toLight / std::sqrt(d2);
        const Color f = evalBSDF(m, sp.n, wo, w);
        if (isBlack(f) || scene.occluded(scene.spawnRayTo(sp, light.position))) continue;
        L += f * light.Le * (std::abs(glm::dot(sp.n, w)) / d2);
    }
    return L;
    //! END
}

}  // namespace ps
