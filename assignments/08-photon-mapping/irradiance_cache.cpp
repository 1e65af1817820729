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
    // TODO(08) Ward's weight w_i of the record at (x, n) (Eq. 8.16; photonmap.h), +infinity at its own point and
    //          normal. Pitfalls (README 6): the square root is on the normal term only; 1 - n . n_i may round below 0.
    (void)rec; (void)x; (void)n;
    return PS_TODO("lesson 08: irradianceWeight", 0.0f);
}

bool interpolateIrradiance(const IrradianceCache& cache, const Vec3& x, const Vec3& n, Color& E) {
    // TODO(08) The cache's irradiance at (x, n) (Eq. 8.17) over the records photonmap.h's interpolateIrradiance
    //          admits; false (E untouched) if none. Pitfalls (README 6): w_i > 1/a, not > a; a record of infinite
    //          weight gives its own E_i (Inf / Inf is NaN). The tests compare at 1e-5: sum in double.
    (void)cache; (void)x; (void)n; (void)E;
    return PS_TODO("lesson 08: interpolateIrradiance", false);
}

IrradianceRecord irradianceRecord(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, int bounces, Rng& rng,
                                  const PhotonMap& global, const PmOptions& opt) {
    // TODO(08) A new record at sp (Eq. 8.18), as irradianceRecord in photonmap.h states it. The tests replay its
    //          random numbers: the cells row by row (j outer, i inner), each cell's first number for i, then the
    //          gather's own. Pitfalls (README 6): the normal turned to wo's side; the cosine-distributed E_i; R_i the
    //          clamped harmonic mean.
    (void)scene; (void)sp; (void)wo; (void)bounces; (void)rng; (void)global; (void)opt;
    return PS_TODO("lesson 08: irradianceRecord", IrradianceRecord());
}

}  // namespace ps
