// Lesson 8 — the radiance estimate: density estimation over the nearest photons. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color radianceEstimate(const PhotonMap& map, const SurfacePoint& sp, const Material& m, const Vec3& wo,
                       const EstimateOptions& opt) {
    // TODO(08) Eq. 8.6: find the photons around sp.p: opt.k > 0: nearestPhotons(k, maxRadius^2),
    //          r^2 = found[0].d2 if k were found, else maxRadius^2; opt.k == 0: photonsInRadius
    //          with r^2 = maxRadius^2. Then L = sum of evalBSDF(m, sp.n, wo, ph.wLight()) * ph.power
    //          * filterKernel(opt.filter, d2, r^2, opt.coneK). No photon: black.
    //          (A thread_local std::vector<NearPhoton> saves an allocation per call.)
    (void)map; (void)sp; (void)m; (void)wo; (void)opt;
    return PS_TODO("lesson 08: radianceEstimate", Color(0.0f));
}

}  // namespace ps
