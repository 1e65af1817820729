// Lesson 6 — the measurement contribution function f(x) of a path, in three-point form.
// Interface: lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

DColor contribution(const Scene& scene, const Path& x) {
    // TODO(06) The measurement contribution f(x) of the path for the pixel it lands in (Eq. 6.3, W_e^(j) of Eq. 4.6;
    //          contribution in paths.h), in double; 0 if k < 1. Pitfalls: evalBSDF in lesson 3's argument order; a
    //          specular vertex gives its delta's coefficient (Eq. 6.11), found with deltaTolerance of the three
    //          vertices (paths.h: far from the origin the positions round the directions past the default).
    (void)scene; (void)x;
    return PS_TODO("lesson 06: contribution", DColor(0.0));
}

}  // namespace ps
