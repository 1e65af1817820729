// Lesson 8 — Ward's irradiance cache: the weight of a record (the split-sphere error bound), the
// interpolation over the records that cover a point, and a new record's gather. Interface:
// lessons/08-photon-mapping/photonmap.h. Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <cmath>
#include <limits>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"
#include "warps.h"

namespace ps {

float irradianceWeight(const IrradianceRecord& rec, const Vec3& x, const Vec3& n) {
    // TODO(08) Eq. 8.16: w_i = 1 / (|x - x_i| / R_i + sqrt(1 - n . n_i)), with 1 - n . n_i
    //          clamped at 0 (rounding); +infinity where the denominator is 0 (the record's own
    //          point and normal).
    (void)rec; (void)x; (void)n;
    return PS_TODO("lesson 08: irradianceWeight", 0.0f);
}

bool interpolateIrradiance(const IrradianceCache& cache, const Vec3& x, const Vec3& n, Color& E) {
    // TODO(08) Eq. 8.17: over cache.records, skip those x is behind ((x - x_i) . (n + n_i) / 2 <
    //          -kCacheBehindTolerance R_i) and those with w_i = irradianceWeight <= 1 / cache.a;
    //          a record of infinite weight: E = its E_i, true. Else E = sum w_i E_i / sum w_i
    //          over the others (accumulate in double), true if there was one, false if none.
    (void)cache; (void)x; (void)n; (void)E;
    return PS_TODO("lesson 08: interpolateIrradiance", false);
}

IrradianceRecord irradianceRecord(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, int bounces, Rng& rng,
                                  const PhotonMap& global, const PmOptions& opt) {
    // TODO(08) Eq. 8.18: n = sp.n turned to wo's side, the frame Frame(n); for each cell (i, j) of
    //          the gatherSide x gatherSide grid (j the row, i the column, j outer), u = ((i +
    //          rng.uniform()) / side, (j + rng.uniform()) / side) (first number for i), the
    //          direction frame.toWorld(sampleCosineHemisphere(u)), its radiance gatherRadiance(
    //          scene, sp, direction, Color(1), bounces, rng, global, opt, &d). Then E_i = pi / M *
    //          sum L (M = side^2), R_i = M / sum 1 / d (a miss adds 0; no hit at all: maxR),
    //          clamped to [opt.minR, opt.maxR]; p = sp.p.
    (void)scene; (void)sp; (void)wo; (void)bounces; (void)rng; (void)global; (void)opt;
    return PS_TODO("lesson 08: irradianceRecord", IrradianceRecord());
}

}  // namespace ps
