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
    //! TODO(08) Ward's weight w_i of the record at (x, n) (Eq. 8.16; photonmap.h), +infinity at its own point and
    //!          normal. Pitfalls (README 6): the square root is on the normal term only; 1 - n . n_i may round below 0.
    //! STUB (void)rec; (void)x; (void)n;
    //! STUB return PS_TODO("lesson 08: irradianceWeight", 0.0f);
    //! BEGIN
    const float error = glm::length(x - rec.p) / rec.R + std::sqrt(std::max(0.0f, 1.0f - glm::dot(n, rec.n)));
    return error > 0.0f ? 1.0f / error : std::numeric_limits<float>::infinity();
    //! END
}

bool interpolateIrradiance(const IrradianceCache& cache, const Vec3& x, const Vec3& n, Color& E) {
    //! TODO(08) The cache's irradiance at (x, n) (Eq. 8.17) over the records photonmap.h's interpolateIrradiance
    //!          admits; false (E untouched) if none. Pitfalls (README 6): w_i > 1/a, not > a; a record of infinite
    //!          weight gives its own E_i (Inf / Inf is NaN). The tests compare at 1e-5: sum in double.
    //! STUB (void)cache; (void)x; (void)n; (void)E;
    //! STUB return PS_TODO("lesson 08: interpolateIrradiance", false);
    //! BEGIN
    double sumW = 0.0, sumR = 0.0, sumG = 0.0, sumB = 0.0;
    for (const IrradianceRecord& rec : cache.records) {
        if (glm::dot(x - rec.p, 0.5f * (n + rec.n)) < -kCacheBehindTolerance * rec.R) continue;
        const float w = irradianceWeight(rec, x, n);
        if (!(w > 1.0f / cache.a)) continue;
        if (std::isinf(w)) {
            E = rec.E;
            return true;
        }
        sumW += w;
        sumR += double(w) * rec.E.r;
        sumG += double(w) * rec.E.g;
        sumB += double(w) * rec.E.b;
    }
    if (sumW == 0.0) return false;
    E = Color(float(sumR / sumW), float(sumG / sumW), float(sumB / sumW));
    return true;
    //! END
}

IrradianceRecord irradianceRecord(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, int bounces, Rng& rng,
                                  const PhotonMap& global, const PmOptions& opt) {
    //! TODO(08) A new record at sp (Eq. 8.18), as irradianceRecord in photonmap.h states it. The tests replay its
    //!          random numbers: the cells row by row (j outer, i inner), each cell's first number for i, then the
    //!          gather's own. Pitfalls (README 6): the normal turned to wo's side; the cosine-distributed E_i; R_i the
    //!          clamped harmonic mean.
    //! STUB (void)scene; (void)sp; (void)wo; (void)bounces; (void)rng; (void)global; (void)opt;
    //! STUB return PS_TODO("lesson 08: irradianceRecord", IrradianceRecord());
    //! BEGIN
    IrradianceRecord rec;
    rec.p = sp.p;
    rec.n = glm::dot(sp.n, wo) < 0.0f ? -sp.n : sp.n;
    const Frame frame(rec.n);
    const int side = opt.gatherSide, M = side * side;
    Color sum(0.0f);
    double inverseDistances = 0.0;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i) {
            const float ux = (float(i) + rng.uniform()) / float(side);
            const float uy = (float(j) + rng.uniform()) / float(side);
            const Vec3 wi = frame.toWorld(sampleCosineHemisphere(Vec2(ux, uy)));
            float d = 0.0f;
            sum += gatherRadiance(scene, sp, wi, Color(1.0f), bounces, rng, global, opt, &d);
            if (std::isfinite(d) && d > 0.0f) inverseDistances += 1.0 / double(d);
        }
    rec.E = sum * (kPi / float(M));
    const float R = inverseDistances > 0.0 ? float(double(M) / inverseDistances) : opt.maxR;
    rec.R = std::clamp(R, opt.minR, opt.maxR);
    return rec;
    //! END
}

}  // namespace ps
