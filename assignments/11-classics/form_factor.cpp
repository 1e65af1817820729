// Lesson 11 — form factors by ray casting (Eq. 11.22-11.26). Interface:
// lessons/11-classics/radiosity.h. Equation numbers refer to lessons/11-classics/README.md.
#include <cmath>
#include "11-classics/radiosity.h"
#include "todo.h"
#include "warps.h"

namespace ps {

float pointFormFactor(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny, float areaY) {
    // TODO(11) The unoccluded point-to-element form factor g of Eq. 11.23 (radiosity.h). Pitfalls (README 6): the 1/pi
    //          (Eq. 11.22); both cosines, each clamped at 0.
    (void)x; (void)nx; (void)y; (void)ny; (void)areaY;
    return PS_TODO("lesson 11: pointFormFactor", 0.0f);
}

float formFactor(const Scene& scene, const ElementMesh& mesh, int i, int j, int samples, Rng& rng) {
    // TODO(11) F_ij by Eq. 11.26, the two techniques and the numbers drawn per sample in the order formFactor in
    //          radiosity.h states (the tests replay them). Pitfalls (README 6): the balance heuristic, not the sum of
    //          both techniques; the cosine technique counts only the first hit, on element j's front.
    (void)scene; (void)mesh; (void)i; (void)j; (void)samples; (void)rng;
    return PS_TODO("lesson 11: formFactor", 0.0f);
}

}  // namespace ps
