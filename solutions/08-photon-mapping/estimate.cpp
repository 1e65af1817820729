// Lesson 8 — the radiance estimate: density estimation over the nearest photons. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color radianceEstimate(const PhotonMap& map, const SurfacePoint& sp, const Material& m, const Vec3& wo,
                       const EstimateOptions& opt) {
    //! TODO(08) Eq. 8.6: find the photons around sp.p: opt.k > 0: nearestPhotons(k, maxRadius^2),
    //!          r^2 = found[0].d2 if k were found, else maxRadius^2; opt.k == 0: photonsInRadius
    //!          with r^2 = maxRadius^2. Then L = sum of evalBSDF(m, sp.n, wo, ph.wLight()) * ph.power
    //!          * filterKernel(opt.filter, d2, r^2, opt.coneK). No photon: black.
    //!          (A thread_local std::vector<NearPhoton> saves an allocation per call.)
    //! STUB (void)map; (void)sp; (void)m; (void)wo; (void)opt;
    //! STUB return PS_TODO("lesson 08: radianceEstimate", Color(0.0f));
    //! BEGIN
    thread_local std::vector<NearPhoton> found;
    const float maxD2 = opt.maxRadius * opt.maxRadius;
    float r2 = maxD2;
    if (opt.k > 0) {
        nearestPhotons(map, sp.p, opt.k, maxD2, found);
        if (found.size() == size_t(opt.k)) r2 = found[0].d2;
    } else {
        photonsInRadius(map, sp.p, maxD2, found);
    }
    Color L(0.0f);
    if (found.empty() || r2 <= 0.0f) return L;
    for (const NearPhoton& q : found) {
        const Photon& ph = map.nodes[q.node];
        L += evalBSDF(m, sp.n, wo, ph.wLight()) * ph.power * filterKernel(opt.filter, q.d2, r2, opt.coneK);
    }
    return L;
    //! END
}

}  // namespace ps
