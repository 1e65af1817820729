// Lesson 11 — Whitted's recursion: mirrors, both branches of glass, point lights and the
// ambient term. Interface: lessons/11-classics/whitted.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/whitted.h"
#include "todo.h"

namespace ps {

Color LiWhitted(const Scene& scene, const Ray& ray, int bounces, const WhittedOptions& opt) {
    //! TODO(11) Eq. 11.9: intersect a copy of ray (scene.intersect(r, sp)); a miss returns
    //!          scene.backgroundRadiance(). At a hit, wo = -ray.d: start from what sp emits
    //!          (emittedRadiance(scene.lights[sp.light], sp.n, wo) if sp.light >= 0); stop there
    //!          if bounces == opt.maxDepth. Else, by the material m:
    //!          - mirror: + m.albedo * LiWhitted(scene.spawnRay(sp, reflect(wo, ns)), bounces + 1)
    //!            with ns the normal on wo's side;
    //!          - glass: g = glassSplit(m, sp.n, wo): + g.reflectance * L(g.reflected) and, if
    //!            g.transmission > 0, + g.transmission * L(g.refracted), both with bounces + 1;
    //!          - otherwise: + whittedDirect(scene, sp, wo) + opt.ambient * m.albedo.
    //!          Pitfall: the ambient term is light that no path carries: only what opt asks.
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
