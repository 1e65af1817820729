// Lesson 11 — Whitted's lights: every point light, through one shadow ray each. Interface:
// lessons/11-classics/whitted.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/whitted.h"
#include "todo.h"

namespace ps {

Color whittedDirect(const Scene& scene, const SurfacePoint& sp, const Vec3& wo) {
    // TODO(11) The light of the point lights at sp towards wo (Eq. 11.7; whitted.h). Pitfalls (README 6): the cosine
    //          at the surface and 1/d^2; the shadow ray ends at the light. Skip a light at distance 0.
    (void)scene; (void)sp; (void)wo;
    return PS_TODO("lesson 11: whittedDirect", Color(0.0f));
}

}  // namespace ps
