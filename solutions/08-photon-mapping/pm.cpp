// Lesson 8 — the photon-mapping estimate of the radiance along a camera ray: direct light,
// specular surfaces, caustics and final gathering. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color LiPhotonMap(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMaps& maps, const PmOptions& opt) {
    //! TODO(08) Eq. 8.11 on lesson 3's cameraWalk(scene, ray, rng, opt.maxDepth, visitor):
    //!          - a miss: the background (scene.backgroundRadiance()) if v.specular; end.
    //!          - an emitter (v.sp.light >= 0) seen with v.specular: add its emittedRadiance.
    //!          - a specular material: go on (the walk samples it).
    //!          - else x = v.sp: add, each times v.beta,
    //!            (a) direct light: sampleDirectLight(scene, sp, wo, rng.uniform(), rng.uniform2())
    //!                .value, if v.bounces < opt.maxDepth;
    //!            (b) caustics: radianceEstimate(maps.caustic, sp, m, wo, opt.causticEstimate);
    //!            (c) final gathering, if v.bounces < opt.maxDepth: sampleBSDF(m, n, wo,
    //!                rng.uniform2(), rng.uniform(), Transport::Radiance, s); follow s.wi through
    //!                specular surfaces (sampling each with sampleBSDF in the same way, multiplying
    //!                the weights; at most maxDepth bounces in all) to the first non-specular
    //!                surface y, and add weight * radianceEstimate(maps.global, y, its material,
    //!                -ray direction, opt.globalEstimate). Emission met on the way is left out.
    //!            and end the walk.
    //! STUB (void)scene; (void)ray; (void)rng; (void)maps; (void)opt;
    //! STUB return PS_TODO("lesson 08: LiPhotonMap", Color(0.0f));
    //! BEGIN
    Color L(0.0f);
    cameraWalk(scene, ray, rng, opt.maxDepth, [&](const WalkVertex& v) {
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
        BSDFSample s;
        const Vec2 u = rng.uniform2();
        const float uLobe = rng.uniform();
        if (!sampleBSDF(m, v.sp.n, v.wo, u, uLobe, Transport::Radiance, s)) return false;
        Color weight = v.beta * s.weight;
        Ray gather = scene.spawnRay(v.sp, s.wi);
        for (int bounces = v.bounces + 1; bounces <= opt.maxDepth && !isBlack(weight); ++bounces) {
            SurfacePoint y;
            if (!scene.intersect(gather, y)) break;
            const Material& my = scene.materials[size_t(y.material)];
            if (!my.isDelta()) {
                L += weight * radianceEstimate(maps.global, y, my, -gather.d, opt.globalEstimate);
                break;
            }
            BSDFSample t;
            const Vec2 ut = rng.uniform2();
            const float uLobeT = rng.uniform();
            if (!sampleBSDF(my, y.n, -gather.d, ut, uLobeT, Transport::Radiance, t)) break;
            weight *= t.weight;
            gather = scene.spawnRay(y, t.wi);
        }
        return false;
    });
    return L;
    //! END
}

}  // namespace ps
