// Lesson 11 — form factors by ray casting (Eq. 11.22-11.26). Interface:
// lessons/11-classics/radiosity.h. Equation numbers refer to lessons/11-classics/README.md.
#include <cmath>
#include "11-classics/radiosity.h"
#include "todo.h"
#include "warps.h"

namespace ps {

float pointFormFactor(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny, float areaY) {
    //! TODO(11) The unoccluded point-to-element form factor g of Eq. 11.23 (radiosity.h). Pitfalls (README 6): the 1/pi
    //!          (Eq. 11.22); both cosines, each clamped at 0.
    //! STUB (void)x; (void)nx; (void)y; (void)ny; (void)areaY;
    //! STUB return PS_TODO("lesson 11: pointFormFactor", 0.0f);
    //! BEGIN
    const Vec3 d = y - x;
    const float r2 = glm::dot(d, d);
    if (!(r2 > 0.0f)) return 0.0f;
    const float r = std::sqrt(r2);
    const float cosX = std::max(0.0f, glm::dot(nx, d) / r);
    const float cosY = std::max(0.0f, -glm::dot(ny, d) / r);
    return areaY * cosX * cosY / (kPi * r2);
    //! END
}

float formFactor(const Scene& scene, const ElementMesh& mesh, int i, int j, int samples, Rng& rng) {
    //! TODO(11) F_ij by Eq. 11.26, the two techniques and the numbers drawn per sample in the order formFactor in
    //!          radiosity.h states (the tests replay them). Pitfalls (README 6): the balance heuristic, not the sum of
    //!          both techniques; the cosine technique counts only the first hit, on element j's front.
    //! STUB (void)scene; (void)mesh; (void)i; (void)j; (void)samples; (void)rng;
    //! STUB return PS_TODO("lesson 11: formFactor", 0.0f);
    //! BEGIN
    if (samples <= 0) return 0.0f;
    const float areaJ = mesh[j].area;
    double sum = 0.0;
    for (int k = 0; k < samples; ++k) {
        const SurfacePoint x = mesh.samplePoint(i, rng.uniform2());
        // The area technique: a point on j.
        const SurfacePoint y = mesh.samplePoint(j, rng.uniform2());
        const float g = pointFormFactor(x.p, x.n, y.p, y.n, areaJ);
        if (g > 0.0f && !scene.occluded(scene.spawnRayTo(x, y))) sum += g / (1.0f + g);
        // The cosine technique: the first hit of a cosine-distributed direction.
        const Vec3 w = Frame(x.n).toWorld(sampleCosineHemisphere(rng.uniform2()));
        Ray ray = scene.spawnRay(x, w);
        SurfacePoint hit;
        if (scene.intersect(ray, hit) && mesh.elementAt(hit, w) == j) {
            const float gh = pointFormFactor(x.p, x.n, hit.p, hit.n, areaJ);
            sum += gh / (1.0f + gh);
        }
    }
    return float(sum / samples);
    //! END
}

}  // namespace ps
