// Lesson 6 — from a pdf per unit solid angle to a pdf per unit area. Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

float pdfSolidAngleToArea(float pdfW, const PathVertex& from, const PathVertex& to) {
    //! TODO(06) Eq. 6.6: pdfW |cos theta_to| / d^2, the density per unit area at `to`.
    //!          Pitfalls: no cosine at a point light or the pinhole; an infinite `to` keeps pdfW
    //!          (its measure is solid angle); d = 0 gives 0.
    //! STUB (void)pdfW; (void)from; (void)to;
    //! STUB return PS_TODO("lesson 06: pdfSolidAngleToArea", 0.0f);
    //! BEGIN
    if (to.infinite) return pdfW;
    const Vec3 d = to.p() - from.p();
    const float d2 = glm::dot(d, d);
    if (!(d2 > 0.0f)) return 0.0f;
    if (to.pointLight || to.pinhole) return pdfW / d2;
    const float cosTo = std::abs(glm::dot(to.sp.n, d)) / std::sqrt(d2);
    return pdfW * cosTo / d2;
    //! END
}

}  // namespace ps
