// Lesson 8 — the radiance estimate: density estimation over the nearest photons. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

Color radianceEstimate(const PhotonMap& map, const SurfacePoint& sp, const Material& m, const Vec3& wo,
                       const EstimateOptions& opt) {
    //! TODO(08) The radiance leaving sp towards wo from the photons around it (Eq. 8.6), as radianceEstimate in
    //!          photonmap.h states it. Pitfalls (README 6): r is the k-th distance only when k photons were found
    //!          (fewer: the maximum radius); the photon's direction is wLight(); 1/pi appears once.
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
