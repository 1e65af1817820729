// Lesson 8 — the photon-mapping estimate of the radiance along a camera ray: direct light,
// specular surfaces, caustics and final gathering (or the irradiance cache). Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <limits>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color gatherRadiance(const Scene& scene, const SurfacePoint& sp, const Vec3& wi, Color weight, int bounces, Rng& rng,
                     const PhotonMap& global, const PmOptions& opt, float* hitDistance) {
    // TODO(08) Final gathering's ray, the last term of Eq. 8.11 (gatherRadiance in photonmap.h): lesson 3's walk
    //          resumed at the gather ray (a WalkStart), without roulette. Pitfalls: emission met on the way is left
    //          out (NEE and the caustic map have it); the start's k counts the bounces before sp.
    (void)scene; (void)sp; (void)wi; (void)weight; (void)bounces; (void)rng; (void)global; (void)opt;
    if (hitDistance) *hitDistance = std::numeric_limits<float>::infinity();
    return PS_TODO("lesson 08: gatherRadiance", Color(0.0f));
}

Color LiPhotonMap(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMaps& maps, const PmOptions& opt) {
    // TODO(08) The radiance along the camera ray by Eq. 8.11 on lesson 3's cameraWalk, term by term as LiPhotonMap in
    //          photonmap.h states it (the cache only at Lambertian x, Eq. 8.17; each gather-visitor hook where set).
    //          The tests replay the random numbers at x (below maxDepth): uLight then uPoint, drawn even where the
    //          visitor refuses the light sample; then the gather's u before uLobe. Pitfalls (README 6): emission
    //          counts only when seen directly or through specular bounces; the cached E becomes radiance through
    //          albedo / pi.
    (void)scene; (void)ray; (void)rng; (void)maps; (void)opt;
    return PS_TODO("lesson 08: LiPhotonMap", Color(0.0f));
}

}  // namespace ps
