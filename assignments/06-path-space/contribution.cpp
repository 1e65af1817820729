// Lesson 6 — the measurement contribution function f(x) of a path, in three-point form.
// Interface: lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

DColor contribution(const Scene& scene, const Path& x) {
    // TODO(06) Eq. 6.3: f(x) = Le(x0 -> x1) * prod over edges of G V * prod over inner vertices of
    //          f_s * W_e^(j)(x_{k-1} -> x_k), W_e^(j) = width * height * camera.We(x_k, direction
    //          from x_k to x_{k-1}) (Eq. 4.6); 0 if k < 1.
    //          Pitfalls: in double (DColor); evalBSDF(m, n, towards the camera, towards the light)
    //          (lesson 3's order); a specular vertex gives deltaLobe's fs, 0 if !lobe.valid (Eq. 6.11).
    //          Pitfall: pass deltaTolerance(x[i-1], x[i], x[i+1]) to deltaLobe: far from the origin
    //          the stored positions round the directions past the default 1e-3.
    (void)scene; (void)x;
    return PS_TODO("lesson 06: contribution", DColor(0.0));
}

}  // namespace ps
