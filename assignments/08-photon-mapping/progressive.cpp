// Lesson 8 — progressive photon mapping: the radius of each pass (Knaus and Zwicker's update) and
// one pass's estimate along a camera ray. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

double ppmNextRadius2(double r2, int pass, double alpha) {
    // TODO(08) r^2 of pass i + 1 from that of pass i >= 1 (Eq. 8.13). Pitfall: r^2 shrinks, not r.
    (void)pass; (void)alpha;
    return PS_TODO("lesson 08: ppmNextRadius2", r2);
}

Color LiProgressive(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMap& map, float r2, int maxDepth) {
    // TODO(08) One pass's radiance along the camera ray (Eq. 8.14) on lesson 3's cameraWalk, as LiProgressive in
    //          photonmap.h states it. Pitfalls (README 6): a fixed-radius box estimate, not k-nearest; emission only
    //          where seen directly or through specular bounces (the estimate at x includes direct light).
    (void)scene; (void)ray; (void)rng; (void)map; (void)r2; (void)maxDepth;
    return PS_TODO("lesson 08: LiProgressive", Color(0.0f));
}

}  // namespace ps
