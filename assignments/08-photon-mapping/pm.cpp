// Lesson 8 — the photon-mapping estimate of the radiance along a camera ray: direct light,
// specular surfaces, caustics and final gathering (or the irradiance cache). Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <limits>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color gatherRadiance(const Scene& scene, const SurfacePoint& sp, const Vec3& wi, Color weight, int bounces, Rng& rng,
                     const PhotonMap& global, const PmOptions& opt, float* hitDistance) {
    // TODO(08) Eq. 8.11, the last term, on lesson 3's camera walk resumed at the gather ray
    //          (cameraWalk from a WalkStart: the ray scene.spawnRay(sp, wi), what it carries,
    //          the k of its first vertex) with no Russian roulette (alwaysSurvive) and
    //          opt.maxDepth. The first vertex's distance goes to *hitDistance (if given; infinity
    //          when nothing is hit). At a non-specular surface y: the radiance is the vertex's
    //          beta times radianceEstimate(global, y, its material, towards sp, opt.globalEstimate),
    //          or the gather visitor's global estimate there if it has one; the walk ends. A
    //          specular surface: the walk samples it and goes on.
    //          Pitfalls: emission met on the way is left out (next-event estimation and the
    //          caustic map have it); the start's k counts the bounces before sp.
    (void)scene; (void)sp; (void)wi; (void)weight; (void)bounces; (void)rng; (void)global; (void)opt;
    if (hitDistance) *hitDistance = std::numeric_limits<float>::infinity();
    return PS_TODO("lesson 08: gatherRadiance", Color(0.0f));
}

Color LiPhotonMap(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMaps& maps, const PmOptions& opt) {
    // TODO(08) Eq. 8.11 on lesson 3's cameraWalk(scene, ray, rng, {opt.maxDepth}, visitor):
    //          - a miss: the background (scene.backgroundRadiance()) if v.specular; end.
    //          - an emitter (v.sp.light >= 0) seen with v.specular: add its emittedRadiance.
    //          - a specular material: go on (the walk samples it).
    //          - else x = v.sp: add, each times v.beta,
    //            (a) direct light: sampleDirectLight(scene, sp, wo, uLight, uPoint).value, if
    //                v.bounces < opt.maxDepth (uLight = rng.uniform() before uPoint = rng.uniform2());
    //            (b) caustics: radianceEstimate(maps.caustic, sp, m, wo, opt.causticEstimate);
    //            (c) the indirect light, if v.bounces < opt.maxDepth:
    //                - irradiance cache (Eq. 8.17): if opt.cache and m is Lambertian
    //                  (BSDFKind::Diffuse) and interpolateIrradiance(*opt.cache, x, n, E) finds
    //                  records (n: the normal on wo's side), add albedo / pi * E (times v.beta);
    //                - otherwise final gathering: sampleBSDF(m, v.sp.n, wo, u, uLobe,
    //                  Transport::Radiance, s) (u = rng.uniform2() before uLobe = rng.uniform())
    //                  and add gatherRadiance(scene, x, s.wi, v.beta * s.weight, v.bounces, rng,
    //                  maps.global, opt);
    //            and end the walk.
    //          The gather visitor (opt.visitor): the emission counts only where it says so
    //          (countsEmission), the light sample likewise (countsLightSample; drawn either way),
    //          its caustic estimate, if it has one, replaces the caustic map's, and the walk goes
    //          on through a specular vertex, or from x to (c), only where it says so
    //          (continuesPast).
    (void)scene; (void)ray; (void)rng; (void)maps; (void)opt;
    return PS_TODO("lesson 08: LiPhotonMap", Color(0.0f));
}

}  // namespace ps
