// Lesson 8 — the photon-mapping estimate of the radiance along a camera ray: direct light,
// specular surfaces, caustics and final gathering (or the irradiance cache). Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <limits>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color gatherRadiance(const Scene& scene, const SurfacePoint& sp, const Vec3& wi, Color weight, int bounces, Rng& rng,
                     const PhotonMap& global, const PmOptions& opt, float* hitDistance) {
    //! TODO(08) Final gathering's ray, the last term of Eq. 8.11 (gatherRadiance in photonmap.h): lesson 3's walk
    //!          resumed at the gather ray (a WalkStart), without roulette. Pitfalls: emission met on the way is left
    //!          out (NEE and the caustic map have it); the start's k counts the bounces before sp.
    //! STUB (void)scene; (void)sp; (void)wi; (void)weight; (void)bounces; (void)rng; (void)global; (void)opt;
    //! STUB if (hitDistance) *hitDistance = std::numeric_limits<float>::infinity();
    //! STUB return PS_TODO("lesson 08: gatherRadiance", Color(0.0f));
    //! BEGIN
    if (hitDistance) *hitDistance = std::numeric_limits<float>::infinity();
    WalkStart gather;
    gather.ray = scene.spawnRay(sp, wi);
    gather.beta = weight;
    gather.bounces = bounces + 1;
    gather.specular = false;
    gather.pPrev = sp.p;
    Color L(0.0f);
    cameraWalk(scene, gather, rng, {opt.maxDepth, alwaysSurvive}, [&](const WalkVertex& y) {
        if (hitDistance && y.bounces == bounces + 1) *hitDistance = y.distance;
        if (!y.hit) return false;
        const Material& my = scene.materials[size_t(y.sp.material)];
        if (my.isDelta()) return true;
        L = y.beta * (opt.visitor.global ? opt.visitor.global(sp, bounces, y.sp, my, y.wo, y.bounces)
                                         : radianceEstimate(global, y.sp, my, y.wo, opt.globalEstimate));
        return false;
    });
    return L;
    //! END
}

Color LiPhotonMap(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMaps& maps, const PmOptions& opt) {
    //! TODO(08) The radiance along the camera ray by Eq. 8.11 on lesson 3's cameraWalk, term by term as LiPhotonMap in
    //!          photonmap.h states it (the cache only at Lambertian x, Eq. 8.17; each gather-visitor hook where set).
    //!          The tests replay the random numbers at x (below maxDepth): uLight then uPoint, drawn even where the
    //!          visitor refuses the light sample; then the gather's u before uLobe. Pitfalls (README 6): emission
    //!          counts only when seen directly or through specular bounces; the cached E becomes radiance through
    //!          albedo / pi.
    //! STUB (void)scene; (void)ray; (void)rng; (void)maps; (void)opt;
    //! STUB return PS_TODO("lesson 08: LiPhotonMap", Color(0.0f));
    //! BEGIN
    Color L(0.0f);
    cameraWalk(scene, ray, rng, {opt.maxDepth}, [&](const WalkVertex& v) {
        if (!v.hit) {
            if (v.specular && opt.visitor.countsEmission(v)) L += v.beta * scene.backgroundRadiance();
            return false;
        }
        if (v.specular && v.sp.light >= 0 && opt.visitor.countsEmission(v))
            L += v.beta * emittedRadiance(scene.lights[size_t(v.sp.light)], v.sp.n, v.wo);
        const Material& m = scene.materials[size_t(v.sp.material)];
        if (m.isDelta()) return opt.visitor.continuesPast(v);
        if (v.bounces < opt.maxDepth) {
            const float uLight = rng.uniform();
            const Vec2 uPoint = rng.uniform2();
            if (opt.visitor.countsLightSample(v))
                L += v.beta * sampleDirectLight(scene, v.sp, v.wo, uLight, uPoint).value;
        }
        L += v.beta * (opt.visitor.caustic ? opt.visitor.caustic(v, m)
                                           : radianceEstimate(maps.caustic, v.sp, m, v.wo, opt.causticEstimate));
        if (v.bounces >= opt.maxDepth || !opt.visitor.continuesPast(v)) return false;
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
