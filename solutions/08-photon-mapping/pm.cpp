// Lesson 8 — the photon-mapping estimate of the radiance along a camera ray: direct light,
// specular surfaces, caustics and final gathering (or the irradiance cache). Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <limits>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color gatherRadiance(const Scene& scene, const SurfacePoint& sp, const Vec3& wi, Color weight, int bounces, Rng& rng,
                     const PhotonMap& global, const PmOptions& opt, float* hitDistance) {
    //! TODO(08) Eq. 8.11, the last term: the gather ray scene.spawnRay(sp, wi). For bounces + 1,
    //!          bounces + 2, ... up to opt.maxDepth, while weight is not black: intersect (a miss:
    //!          black); the first hit's distance goes to *hitDistance (if given; infinity when
    //!          nothing is hit). At a non-specular surface y: return weight * radianceEstimate(
    //!          global, y, its material, -ray direction, opt.globalEstimate). At a specular one:
    //!          sampleBSDF(material, y.n, -ray direction, u, uLobe, Transport::Radiance, s)
    //!          (u = rng.uniform2() drawn before uLobe = rng.uniform(); a failed sample: black),
    //!          weight *= s.weight, and go on from y in direction s.wi. Emission met on the way
    //!          is left out.
    //! STUB (void)scene; (void)sp; (void)wi; (void)weight; (void)bounces; (void)rng; (void)global; (void)opt;
    //! STUB if (hitDistance) *hitDistance = std::numeric_limits<float>::infinity();
    //! STUB return PS_TODO("lesson 08: gatherRadiance", Color(0.0f));
    //! BEGIN
    if (hitDistance) *hitDistance = std::numeric_limits<float>::infinity();
    Ray gather = scene.spawnRay(sp, wi);
    for (int b = bounces + 1; b <= opt.maxDepth && !isBlack(weight); ++b) {
        SurfacePoint y;
        if (!scene.intersect(gather, y)) break;
        if (hitDistance && b == bounces + 1) *hitDistance = gather.tMax;
        const Material& my = scene.materials[size_t(y.material)];
        if (!my.isDelta()) return weight * radianceEstimate(global, y, my, -gather.d, opt.globalEstimate);
        BSDFSample t;
        const Vec2 ut = rng.uniform2();
        const float uLobeT = rng.uniform();
        if (!sampleBSDF(my, y.n, -gather.d, ut, uLobeT, Transport::Radiance, t)) break;
        weight *= t.weight;
        gather = scene.spawnRay(y, t.wi);
    }
    return Color(0.0f);
    //! END
}

Color LiPhotonMap(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMaps& maps, const PmOptions& opt) {
    //! TODO(08) Eq. 8.11 on lesson 3's cameraWalk(scene, ray, rng, {opt.maxDepth}, visitor):
    //!          - a miss: the background (scene.backgroundRadiance()) if v.specular; end.
    //!          - an emitter (v.sp.light >= 0) seen with v.specular: add its emittedRadiance.
    //!          - a specular material: go on (the walk samples it).
    //!          - else x = v.sp: add, each times v.beta,
    //!            (a) direct light: sampleDirectLight(scene, sp, wo, uLight, uPoint).value, if
    //!                v.bounces < opt.maxDepth (uLight = rng.uniform() before uPoint = rng.uniform2());
    //!            (b) caustics: radianceEstimate(maps.caustic, sp, m, wo, opt.causticEstimate);
    //!            (c) the indirect light, if v.bounces < opt.maxDepth:
    //!                - irradiance cache (Eq. 8.17): if opt.cache and m is Lambertian
    //!                  (BSDFKind::Diffuse) and interpolateIrradiance(*opt.cache, x, n, E) finds
    //!                  records (n: the normal on wo's side), add albedo / pi * E (times v.beta);
    //!                - otherwise final gathering: sampleBSDF(m, v.sp.n, wo, u, uLobe,
    //!                  Transport::Radiance, s) (u = rng.uniform2() before uLobe = rng.uniform())
    //!                  and add gatherRadiance(scene, x, s.wi, v.beta * s.weight, v.bounces, rng,
    //!                  maps.global, opt);
    //!            and end the walk.
    //! STUB (void)scene; (void)ray; (void)rng; (void)maps; (void)opt;
    //! STUB return PS_TODO("lesson 08: LiPhotonMap", Color(0.0f));
    //! BEGIN
    Color L(0.0f);
    cameraWalk(scene, ray, rng, {opt.maxDepth}, [&](const WalkVertex& v) {
        if (!v.hit) {
            if (v.specular) L += v.beta * scene.backgroundRadiance();
            return false;
        }
        if (v.specular && v.sp.light >= 0)
            L += v.beta * emittedRadiance(scene.lights[size_t(v.sp.light)], v.sp.n, v.wo);
        const Material& m = scene.materials[size_t(v.sp.material)];
        if (m.isDelta()) return true;
        if (v.bounces < opt.maxDepth) {
            const float uLight = rng.uniform();
            const Vec2 uPoint = rng.uniform2();
            L += v.beta * sampleDirectLight(scene, v.sp, v.wo, uLight, uPoint).value;
        }
        L += v.beta * radianceEstimate(maps.caustic, v.sp, m, v.wo, opt.causticEstimate);
        if (v.bounces >= opt.maxDepth) return false;
        if (opt.cache && m.kind == BSDFKind::Diffuse) {
            const Vec3 n = glm::dot(v.sp.n, v.wo) < 0.0f ? -v.sp.n : v.sp.n;
            Color E;
            if (interpolateIrradiance(*opt.cache, v.sp.p, n, E)) {
                L += v.beta * (m.albedo * kInvPi) * E;
                return false;
            }
        }
        BSDFSample s;
        const Vec2 u = rng.uniform2();
        const float uLobe = rng.uniform();
        if (!sampleBSDF(m, v.sp.n, v.wo, u, uLobe, Transport::Radiance, s)) return false;
        L += gatherRadiance(scene, v.sp, s.wi, v.beta * s.weight, v.bounces, rng, maps.global, opt);
        return false;
    });
    return L;
    //! END
}

}  // namespace ps
