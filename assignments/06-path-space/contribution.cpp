// Lesson 6 — the measurement contribution function f(x) of a path, in three-point form.
// Interface: lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

DColor contribution(const Scene& scene, const Path& x) {
    // TODO(06) f(x) of Eq. 6.3 for x = x[0] ... x[k], k = x.size() - 1 (0 if k < 1):
    //          Accumulate in double (DColor): the product leaves the float range at extreme scales.
//          1. Le(x0 -> x1): light = scene.lights[x[0].sp.light]; a point light or the
    //             background: light.Le; an area light: emittedRadiance(light, x[0].sp.n,
    //             direction(x[0], x[1])).
    //          2. Every edge i = 0 ... k-1: 0 if !visible(scene, x[i], x[i+1]); times
    //             geometryTerm(x[i], x[i+1]).
    //          3. Every inner vertex i = 1 ... k-1, with wLight = direction(x[i], x[i-1]) and
    //             wCamera = direction(x[i], x[i+1]) and m its material: radiance flows from
    //             wLight to wCamera, so f_s = evalBSDF(m, n, wCamera, wLight) (lesson 3's
    //             argument order: wo towards the camera); a specular vertex (x[i].specular):
    //             lobe = deltaLobe(m, n, wLight, wCamera), f_s = lobe.fs, 0 if !lobe.valid
    //             (the coefficient of the delta, Eq. 6.11, never a huge number).
    //          4. The pixel's sensor at the pinhole x[k] (lesson 4, Eq. 4.6): width * height *
    //             camera.We(direction(x[k], x[k-1])).
    (void)scene; (void)x;
    return PS_TODO("lesson 06: contribution", DColor(0.0));
}

}  // namespace ps
