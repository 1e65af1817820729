// Lesson 11 — form factors by ray casting (Eq. 11.22-11.26). Interface:
// lessons/11-classics/radiosity.h. Equation numbers refer to lessons/11-classics/README.md.
#include <cmath>
#include "11-classics/radiosity.h"
#include "todo.h"
#include "warps.h"

namespace ps {

float pointFormFactor(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny, float areaY) {
    // TODO(11) Eq. 11.23: g = areaY cos+(theta_x) cos+(theta_y) / (pi r^2) with d = y - x,
    //          r^2 = d . d, cos(theta_x) = nx . d / r, cos(theta_y) = -ny . d / r, each cosine
    //          clamped below at 0 (an element faces one way); 0 when r^2 = 0.
    //          Pitfall: the 1/pi makes the form factors of a closed room sum to 1 (Eq. 11.22);
    //          and both cosines are needed (the area of each element as the other sees it).
    (void)x; (void)nx; (void)y; (void)ny; (void)areaY;
    return PS_TODO("lesson 11: pointFormFactor", 0.0f);
}

float formFactor(const Scene& scene, const ElementMesh& mesh, int i, int j, int samples, Rng& rng) {
    // TODO(11) Eq. 11.26: for each of `samples` samples:
    //          - x = mesh.samplePoint(i, rng.uniform2()) (its normal x.n faces the element's front);
    //          - area technique: y = mesh.samplePoint(j, rng.uniform2()), g = pointFormFactor(x.p,
    //            x.n, y.p, y.n, A_j); if g > 0 and !scene.occluded(scene.spawnRayTo(x, y)), add g / (1 + g);
    //          - cosine technique: w = Frame(x.n).toWorld(sampleCosineHemisphere(rng.uniform2())),
    //            ray = scene.spawnRay(x, w); if scene.intersect(ray, hit) and mesh.elementAt(hit,
    //            w) == j, add g / (1 + g) with g = pointFormFactor(x.p, x.n, hit.p, hit.n, A_j).
    //          Return the sum / samples (0 for samples <= 0).
    //          Pitfall: g / (1 + g) is the balance heuristic's weight times each technique's
    //          estimate (Eq. 11.26); adding g (area) and 1 (cosine) counts F twice, and area
    //          sampling alone has infinite variance for elements that share an edge (Eq. 11.25).
    (void)scene; (void)mesh; (void)i; (void)j; (void)samples; (void)rng;
    return PS_TODO("lesson 11: formFactor", 0.0f);
}

}  // namespace ps
