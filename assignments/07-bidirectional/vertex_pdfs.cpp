// Lesson 7 — the densities of path vertices (Eq. 7.3): one set of functions for sampling the
// subpaths and for the MIS weights, so that the 1/d^2 of a short connection cancels exactly.
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

float convertToArea(float pdfW, const SubpathVertex& from, const SubpathVertex& to) {
    // TODO(07) Eq. 7.3: if `to` is at infinity return pdfW unchanged; else w = to.sp.p - from.sp.p,
    //          d2 = |w|^2, 0 if d2 is 0; pdf = pdfW / d2, times |cos| = |dot(to.sp.n, w)| / sqrt(d2)
    //          if to.onSurface().
    (void)pdfW; (void)from; (void)to;
    return PS_TODO("lesson 07: convertToArea", 0.0f);
}

float pdfLightOrigin(const Scene& scene, const SubpathVertex& v) {
    // TODO(07) Eq. 7.3: P = scene.lightSelectionProb(v.light) (0 if v.light < 0); background:
    //          P * pdfBackgroundDirection(); point light: P; area light: P * pdfLightArea(scene, l).
    (void)scene; (void)v;
    return PS_TODO("lesson 07: pdfLightOrigin", 0.0f);
}

float pdfLightToward(const Scene& scene, const SubpathVertex& light, const SubpathVertex& to) {
    // TODO(07) Eq. 7.3, the densities sampleEmission uses: background: 1 / (pi R^2) with
    //          R = scene.radius, times |dot(to.sp.n, light.sp.n)| if to.onSurface() (parallel
    //          rays from a disk); point light: convertToArea(1 / (4 pi)); area light: the
    //          cosine density max(0, dot(light.sp.n, w)) / pi of the unit direction w from the
    //          light to `to`, through convertToArea.
    (void)scene; (void)light; (void)to;
    return PS_TODO("lesson 07: pdfLightToward", 0.0f);
}

float pdfScatter(const Scene& scene, const SubpathVertex* prev, const SubpathVertex& cur, const SubpathVertex& next,
                 Transport mode) {
    // TODO(07) Eq. 7.3, 7.7a: the unit direction wn = directionTo(cur, next) (bpt.h); camera:
    //          pdfW = scene.camera.pdfDirection(wn); surface (prev not null), wp =
    //          directionTo(cur, *prev), m its material: not delta: pdfW = pdfBSDF(m, cur.sp.n, wp, wn);
    //          delta: the coefficient of its Dirac delta from lesson 6's deltaLobe (paths.h), NOT 0:
    //          mode Importance (light flows from prev to next): deltaLobe(m, n, wp, wn).pdfLight;
    //          mode Radiance (light flows from next to prev): deltaLobe(m, n, wn, wp).pdfCamera;
    //          (use its numbers even if lobe.valid is false: the walk itself chose this direction,
    //          and on a very short segment rounding of the positions can exceed deltaLobe's
    //          tolerance; they are 0 only if no lobe connects the two sides). Return
    //          convertToArea(pdfW, cur, next).
    (void)scene; (void)prev; (void)cur; (void)next; (void)mode;
    return PS_TODO("lesson 07: pdfScatter", 0.0f);
}

}  // namespace ps
