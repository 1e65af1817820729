// Lesson 8 — the radiance estimate: density estimation over the nearest photons. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color radianceEstimate(const PhotonMap& map, const SurfacePoint& sp, const Material& m, const Vec3& wo,
                       const EstimateOptions& opt) {
    // TODO(08) The radiance leaving sp towards wo from the photons around it (Eq. 8.6), as radianceEstimate in
    //          photonmap.h states it. Pitfalls (README 6): r is the k-th distance only when k photons were found
    //          (fewer: the maximum radius); the photon's direction is wLight(); 1/pi appears once.
    (void)map; (void)sp; (void)m; (void)wo; (void)opt;
    return PS_TODO("lesson 08: radianceEstimate", Color(0.0f));
}

}  // namespace ps
