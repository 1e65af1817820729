// Lesson 8 — progressive photon mapping: the radius of each pass (Knaus and Zwicker's update) and
// one pass's estimate along a camera ray. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

double ppmNextRadius2(double r2, int pass, double alpha) {
    // TODO(08) Eq. 8.13: r_{i+1}^2 = r_i^2 (i + alpha) / (i + 1), i = pass >= 1.
    (void)pass; (void)alpha;
    return PS_TODO("lesson 08: ppmNextRadius2", r2);
}

Color LiProgressive(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMap& map, float r2, int maxDepth) {
    // TODO(08) Eq. 8.14 on lesson 3's cameraWalk(scene, ray, rng, {maxDepth}, visitor):
    //          - a miss: the background (scene.backgroundRadiance()) if v.specular; end.
    //          - an emitter (v.sp.light >= 0) seen with v.specular: add its emittedRadiance.
    //          - a specular material: go on.
    //          - else, if v.bounces < maxDepth, add v.beta * radianceEstimate(map, sp, m, wo, opt)
    //            with opt: Filter::Box, k = 0 (fixed radius), maxRadius = sqrt(r2); end the walk.
    (void)scene; (void)ray; (void)rng; (void)map; (void)r2; (void)maxDepth;
    return PS_TODO("lesson 08: LiProgressive", Color(0.0f));
}

}  // namespace ps
