// Lesson 6 — the area-measure pdf p_{s,t}(x) of a path under technique (s, t). Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

double pdfTechnique(const Scene& scene, const Path& x, int s) {
    // TODO(06) p_{s,t}(x) = p(light subpath) p(camera subpath) (Eq. 6.7-6.10), multiplied in
    //          double (a long path's pdf leaves the float range at extreme scales), for k = x.size() - 1 and t = k + 1 - s:
    //          0. Techniques that cannot sample x return 0 (Eq. 6.12): k < 1, s < 0, t < 1
    //             (t = 0 would need a ray to hit the pinhole); s = 0 with x[0] a point light;
    //             s >= 1 and x[s-1] or x[s] specular (the joining edge cannot follow a delta);
    //             t = 1 with x[k-1] at infinity (k = 1, s = 1: a background direction is not
    //             a point that could be joined to the pinhole; no sampler makes that path).
    //          1. Light subpath (s >= 1), light l = x[0].sp.light, P = scene.lightSelectionProb(l):
    //             p(x0) = P * pdfLightArea(scene, l) for an area light (the same number as
    //             sampleEmission's pdfA, and sampleLight's pdf: one light pdf for s = 1 and s > 1);
    //             P alone for a point light (a delta position: a flag, Eq. 6.11) or the
    //             background (whose x0 is a direction: P * pdfBackgroundDirection()).
    //             If s >= 2, x1 given x0: an area light emits by the cosine, pdfW =
    //             max(0, dot(x0.n, w)) / pi, w = direction(x[0], x[1]); a point light
    //             uniformly, pdfW = uniformSpherePdf(); either way times
    //             pdfSolidAngleToArea(pdfW, x[0], x[1]). The background: x1 is the disk point
    //             sampleEmission chose: 1 / (pi scene.radius^2) |dot(x[1].sp.n, x[0].sp.n)|.
    //             Each next x_{i+1}, i = 1 ... s-2, sampled at x_i in Importance mode from
    //             wLight = direction(x[i], x[i-1]) towards wNext = direction(x[i], x[i+1]):
    //             pdfW = pdfBSDF(m, n, wLight, wNext), or for a specular x_i
    //             deltaLobe(m, n, wLight, wNext).pdfLight (0 if not valid); times
    //             pdfSolidAngleToArea(pdfW, x[i], x[i+1]).
    //          2. Camera subpath (t >= 1): the pinhole x_k has probability 1 (a delta
    //             position). If t >= 2, x_{k-1}: camera.pdfDirection(direction(x[k], x[k-1]))
    //             converted with pdfSolidAngleToArea(., x[k], x[k-1]). Each next x_{j-1},
    //             j = k-1 ... s+1, sampled at x_j in Radiance mode from wCamera =
    //             direction(x[j], x[j+1]) towards wPrev = direction(x[j], x[j-1]):
    //             pdfBSDF(m, n, wCamera, wPrev), or for a specular x_j
    //             deltaLobe(m, n, wPrev, wCamera).pdfCamera (0 if not valid); converted to x[j-1].
    //          3. The joining edge x[s-1] x[s] is deterministic: no factor. No Russian roulette.
    (void)scene; (void)x; (void)s;
    return PS_TODO("lesson 06: pdfTechnique", 0.0);
}

}  // namespace ps
