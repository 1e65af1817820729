// Lesson 12 — the adjoint from the learned field, and the decision of a camera path on it.
// Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md and lessons/10-adrrs/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

Color fieldAdjoint(const GuideCell& cell, const Material& m, const Vec3& n, const Vec3& wo) {
    // TODO(12) The adjoint of Eq. 12.14 at a vertex, as guiding.h states it. Pitfall (README 6): the side is
    //          the one wo sees (AdjointCache::side); the two faces of a wall see different rooms.
    (void)cell; (void)m; (void)n; (void)wo;
    return PS_TODO("lesson 12: fieldAdjoint", Color(0.0f));
}

float fieldPixelEstimate(const GuideField& field, const Scene& scene, const WalkVertex& x0) {
    // TODO(12) The pixel estimate of Eq. 10.9 from the field, or -1 where it cannot say (guiding.h).
    (void)field; (void)scene; (void)x0;
    return PS_TODO("lesson 12: fieldPixelEstimate", -1.0f);
}

Decision fieldDecision(const GuideField& field, const Scene& scene, const WalkVertex& v, float pixelEstimate) {
    // TODO(12) The decision at v (Eq. 12.14, 12.15; guiding.h), none where the field cannot say.
    //          Pitfall (README 6): look the field up where the path is, on the side v.wo sees.
    (void)field; (void)scene; (void)v; (void)pixelEstimate;
    return PS_TODO("lesson 12: fieldDecision", Decision());
}

}  // namespace ps
