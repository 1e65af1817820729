// Lesson 6 — the area-measure pdf p_{s,t}(x) of a path under technique (s, t). Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

double pdfTechnique(const Scene& scene, const Path& x, int s) {
    // TODO(06) Eq. 6.7-6.10: p_{s,t}(x) = p(light subpath x0 .. x_{s-1}) * p(camera subpath x_k .. x_s),
    //          each vertex's density converted to area at it (pdfSolidAngleToArea); the joining
    //          edge is free. x0 and x1 as startLightPath samples them: P(l) and pdfEmission's
    //          pdfA, pdfW (the background's x0 is a direction: pdfW; its x1 the disk point: pdfA |cos|);
    //          then pdfBSDF, or deltaLobe's pdfLight / pdfCamera at a specular vertex (Eq. 6.11).
    //          (with deltaTolerance of the vertex and its two neighbours, as in contribution).
    //          The camera subpath starts with camera.pdfPoint() (1 for the pinhole) and
    //          camera.pdfDirection(x_k, ...).
    //          Pitfalls: 0 for what cannot be sampled (Eq. 6.12: t < 1, s = 0 at a point light, a
    //          specular end of the joining edge, t = 1 with x_{k-1} the background); in double;
    //          pdfBSDF's first argument is the direction the walk arrived from; no Russian roulette.
    //          (A camera model: t = 0 when x_k is its point, x[k].onCamera: the light subpath samples
    //          every vertex, x_k included, and there is no joining edge.)
    (void)scene; (void)x; (void)s;
    return PS_TODO("lesson 06: pdfTechnique", 0.0);
}

}  // namespace ps
