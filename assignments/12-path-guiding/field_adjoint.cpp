// Lesson 12 — the adjoint from the learned field, and the decision of a camera path on it.
// Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md and lessons/10-adrrs/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

Color fieldAdjoint(const GuideCell& cell, const Material& m, const Vec3& n, const Vec3& wo) {
    // TODO(12) Eq. 12.14: the albedo over pi times the irradiance of the cell's side that wo sees
    //          (cell.side[AdjointCache::side(n, wo)]).
    //          Pitfall: the side is that of the normal turned towards wo: the two faces of a wall
    //          see different rooms.
    (void)cell; (void)m; (void)n; (void)wo;
    return PS_TODO("lesson 12: fieldAdjoint", Color(0.0f));
}

float fieldPixelEstimate(const GuideField& field, const Scene& scene, const WalkVertex& x0) {
    // TODO(12) Eq. 10.9 on the field: -1 at a miss, a delta material, or where the side of x0's
    //          cell (field.cellOf(x0.sp.p)) that x0.wo sees is not reliable; else the mean of the
    //          channels of fieldAdjoint there.
    (void)field; (void)scene; (void)x0;
    return PS_TODO("lesson 12: fieldPixelEstimate", -1.0f);
}

Decision fieldDecision(const GuideField& field, const Scene& scene, const WalkVertex& v, float pixelEstimate) {
    // TODO(12) Eq. 12.14, 12.15: no decision where pixelEstimate < 0, at a miss, at a delta
    //          material or where the side of v's cell that v.wo sees is not reliable; else decided,
    //          with q from windowContinuations(v.beta, fieldAdjoint at v, pixelEstimate).
    //          Pitfall: look the field up where the path is (v.sp.p), not where it came from.
    (void)field; (void)scene; (void)v; (void)pixelEstimate;
    return PS_TODO("lesson 12: fieldDecision", Decision());
}

}  // namespace ps
