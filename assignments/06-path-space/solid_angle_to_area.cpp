// Lesson 6 — from a pdf per unit solid angle to a pdf per unit area. Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

float pdfSolidAngleToArea(float pdfW, const PathVertex& from, const PathVertex& to) {
    // TODO(06) The Jacobian d omega / dA of Eq. 6.6: a direction sampled at `from` with
    //          density pdfW (per unit solid angle) hits `to` with density pdfW |cos theta_to| / d^2
    //          per unit area at `to`, where d = |to - from| and cos theta_to = dot(to.sp.n, w),
    //          w the unit direction between them.
    //          - `to` infinite: its measure is solid angle; return pdfW unchanged.
    //          - `to` a point light or the pinhole (no surface there): no cosine, pdfW / d^2.
    //          - d = 0: return 0.
    (void)pdfW; (void)from; (void)to;
    return PS_TODO("lesson 06: pdfSolidAngleToArea", 0.0f);
}

}  // namespace ps
