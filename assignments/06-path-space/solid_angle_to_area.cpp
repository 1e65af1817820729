// Lesson 6 — from a pdf per unit solid angle to a pdf per unit area. Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

float pdfSolidAngleToArea(float pdfW, const PathVertex& from, const PathVertex& to) {
    // TODO(06) Eq. 6.6: pdfW |cos theta_to| / d^2, the density per unit area at `to`.
    //          Pitfalls: no cosine at a point light or the pinhole; an infinite `to` keeps pdfW
    //          (its measure is solid angle); d = 0 gives 0.
    (void)pdfW; (void)from; (void)to;
    return PS_TODO("lesson 06: pdfSolidAngleToArea", 0.0f);
}

}  // namespace ps
