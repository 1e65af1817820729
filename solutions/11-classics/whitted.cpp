// Lesson 11 — Whitted's recursion: mirrors, both branches of glass, point lights and the
// ambient term. Interface: lessons/11-classics/whitted.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/whitted.h"
#include "todo.h"

namespace ps {

Color LiWhitted(const Scene& scene, const Ray& ray, int bounces, const WhittedOptions& opt) {
    //! TODO(11) Whitted's recursion, Eq. 11.9, as LiWhitted in whitted.h states it. Pitfalls (README 6): a surface
    //!          reached after maxDepth bounces only emits; the ambient term only where shaded and only what opt asks.
    //! STUB (void)scene; (void)ray; (void)bounces; (void)opt;
    //! STUB return PS_TODO("lesson 11: LiWhitted", Color(0.0f));
    //! BEGIN
    SurfacePoint sp;
    if (Ray r = ray; !scene.intersect(r, sp)) return scene.backgroundRadiance();  // a miss
    const Vec3 wo = -ray.d;
    Color L(0.0f);
    if (sp.light >= 0) L += emittedRadiance(scene.lights[size_t(sp.light)], sp.n, wo);
    if (bounces >= opt.maxDepth) return L;
    const Material& m = scene.materials[size_t(sp.material)];
    if (m.kind == BSDFKind::Mirror) {
        const Vec3 ns = glm::dot(sp.n, wo) < 0.0f ? -sp.n : sp.n;
        return L + m.albedo * LiWhitted(scene, scene.spawnRay(sp, reflect(wo, ns)), bounces + 1, opt);
    }
    if (m.kind == BSDFKind::Dielectric) {
        const GlassSplit g = glassSplit(m, sp.n, wo);
        L += g.reflectance * LiWhitted(scene, scene.spawnRay(sp, g.reflected), bounces + 1, opt);
        if (g.transmission > 0.0f)
            L += g.transmission * LiWhitted(scene, scene.spawnRay(sp, g.refracted), bounces + 1, opt);
        return L;
    }
    return L + whittedDirect(scene, sp, wo) + opt.ambient * m.albedo;
    //! END
}

}  // namespace ps
