// Lesson 6 — from a pdf per unit solid angle to a pdf per unit area. Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

float pdfSolidAngleToArea(float pdfW, const PathVertex& from, const PathVertex& to) {
    // TODO(06) pdfW as a density per unit area at `to` (Eq. 6.6; paths.h), 0 for d = 0. Pitfalls (README 6): only the
    //          cosine at `to`, none at a point light or the pinhole; an infinite `to` keeps solid angle.
    (void)pdfW; (void)from; (void)to;
    return PS_TODO("lesson 06: pdfSolidAngleToArea", 0.0f);
}

}  // namespace ps
