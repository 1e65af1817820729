// Lesson 7 — the densities of path vertices (Eq. 7.3): one set of functions for sampling the
// subpaths and for the MIS weights, so that the 1/d^2 of a short connection cancels exactly.
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

float pdfLightOrigin(const Scene& scene, const PathVertex& v) {
    // TODO(07) The density of the light vertex v itself (Eq. 7.3; pdfLightOrigin in bpt.h). Pitfall: P(l); 0 on no
    //          light.
    (void)scene; (void)v;
    return PS_TODO("lesson 07: pdfLightOrigin", 0.0f);
}

float pdfLightToward(const Scene& scene, const PathVertex& light, const PathVertex& to) {
    // TODO(07) The area density of the emitted direction at `to` (Eq. 7.3; pdfLightToward in bpt.h), the background's
    //          from its disk. Pitfall: 0 on no light.
    (void)scene; (void)light; (void)to;
    return PS_TODO("lesson 07: pdfLightToward", 0.0f);
}

float pdfScatter(const Scene& scene, const PathVertex* prev, const PathVertex& cur, const PathVertex& next,
                 Transport mode) {
    // TODO(07) The area density with which cur samples next (Eq. 7.3, 7.7a; pdfScatter in bpt.h), walking in `mode`.
    //          Pitfalls (README 6): a specular cur's density is its delta's coefficient, not 0, even when the lobe is
    //          not valid; the BSDF's arguments in the walk's order.
    (void)scene; (void)prev; (void)cur; (void)next; (void)mode;
    return PS_TODO("lesson 07: pdfScatter", 0.0f);
}

}  // namespace ps
