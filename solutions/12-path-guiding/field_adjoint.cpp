// Lesson 12 — the adjoint from the learned field, and the decision of a camera path on it.
// Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md and lessons/10-adrrs/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

Color fieldAdjoint(const GuideCell& cell, const Material& m, const Vec3& n, const Vec3& wo) {
    //! TODO(12) Eq. 12.14: the albedo over pi times the irradiance of the cell's side that wo sees
    //!          (cell.side[AdjointCache::side(n, wo)]).
    //!          Pitfall: the side is that of the normal turned towards wo: the two faces of a wall
    //!          see different rooms.
    //! STUB (void)cell; (void)m; (void)n; (void)wo;
    //! STUB return PS_TODO("lesson 12: fieldAdjoint", Color(0.0f));
    //! BEGIN
    return m.albedo * (kInvPi * cell.side[AdjointCache::side(n, wo)].irradiance);
    //! END
}

float fieldPixelEstimate(const GuideField& field, const Scene& scene, const WalkVertex& x0) {
    //! TODO(12) Eq. 10.9 on the field: -1 at a miss, a delta material, or where the side of x0's
    //!          cell (field.cellOf(x0.sp.p)) that x0.wo sees is not reliable; else the mean of the
    //!          channels of fieldAdjoint there.
    //! STUB (void)field; (void)scene; (void)x0;
    //! STUB return PS_TODO("lesson 12: fieldPixelEstimate", -1.0f);
    //! BEGIN
    if (!x0.hit) return -1.0f;
    const Material& m = scene.materials[x0.sp.material];
    const GuideCell& c = field.cell(field.cellOf(x0.sp.p));
    if (m.isDelta() || !c.side[AdjointCache::side(x0.sp.n, x0.wo)].reliable) return -1.0f;
    const Color a = fieldAdjoint(c, m, x0.sp.n, x0.wo);
    return (a.r + a.g + a.b) / 3.0f;
    //! END
}

Decision fieldDecision(const GuideField& field, const Scene& scene, const WalkVertex& v, float pixelEstimate) {
    //! TODO(12) Eq. 12.14, 12.15: no decision where pixelEstimate < 0, at a miss, at a delta
    //!          material or where the side of v's cell that v.wo sees is not reliable; else decided,
    //!          with q from windowContinuations(v.beta, fieldAdjoint at v, pixelEstimate).
    //!          Pitfall: look the field up where the path is (v.sp.p), not where it came from.
    //! STUB (void)field; (void)scene; (void)v; (void)pixelEstimate;
    //! STUB return PS_TODO("lesson 12: fieldDecision", Decision());
    //! BEGIN
    if (pixelEstimate < 0.0f || !v.hit) return Decision();
    const Material& m = scene.materials[v.sp.material];
    const GuideCell& c = field.cell(field.cellOf(v.sp.p));
    if (m.isDelta() || !c.side[AdjointCache::side(v.sp.n, v.wo)].reliable) return Decision();
    return {true, windowContinuations(v.beta, fieldAdjoint(c, m, v.sp.n, v.wo), pixelEstimate)};
    //! END
}

}  // namespace ps
