// Lesson 8 — the photon-mapping estimate of the radiance along a camera ray: direct light,
// specular surfaces, caustics and final gathering. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color LiPhotonMap(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMaps& maps, const PmOptions& opt) {
    // TODO(08) Eq. 8.11 on lesson 3's cameraWalk(scene, ray, rng, opt.maxDepth, visitor):
    //          - a miss: the background (scene.backgroundRadiance()) if v.specular; end.
    //          - an emitter (v.sp.light >= 0) seen with v.specular: add its emittedRadiance.
    //          - a specular material: go on (the walk samples it).
    //          - else x = v.sp: add, each times v.beta,
    //            (a) direct light: sampleDirectLight(scene, sp, wo, rng.uniform(), rng.uniform2())
    //                .value, if v.bounces < opt.maxDepth;
    //            (b) caustics: radianceEstimate(maps.caustic, sp, m, wo, opt.causticEstimate);
    //            (c) final gathering, if v.bounces < opt.maxDepth: sampleBSDF(m, n, wo,
    //                rng.uniform2(), rng.uniform(), Transport::Radiance, s); follow s.wi through
    //                specular surfaces (sampling each with sampleBSDF in the same way, multiplying
    //                the weights; at most maxDepth bounces in all) to the first non-specular
    //                surface y, and add weight * radianceEstimate(maps.global, y, its material,
    //                -ray direction, opt.globalEstimate). Emission met on the way is left out.
    //            and end the walk.
    (void)scene; (void)ray; (void)rng; (void)maps; (void)opt;
    return PS_TODO("lesson 08: LiPhotonMap", Color(0.0f));
}

}  // namespace ps
