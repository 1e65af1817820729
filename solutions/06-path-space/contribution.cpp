// Lesson 6 — the measurement contribution function f(x) of a path, in three-point form.
// Interface: lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

DColor contribution(const Scene& scene, const Path& x) {
    //! TODO(06) Eq. 6.3: f(x) = Le(x0 -> x1) * prod over edges of G V * prod over inner vertices of
    //!          f_s * W_e^(j)(x_{k-1} -> x_k), W_e^(j) = width * height * camera.We(x_k, direction
    //!          from x_k to x_{k-1}) (Eq. 4.6); 0 if k < 1.
    //!          Pitfalls: in double (DColor); evalBSDF(m, n, towards the camera, towards the light)
    //!          (lesson 3's order); a specular vertex gives deltaLobe's fs, 0 if !lobe.valid (Eq. 6.11).
    //!          Pitfall: pass deltaTolerance(x[i-1], x[i], x[i+1]) to deltaLobe: far from the origin
    //!          the stored positions round the directions past the default 1e-3.
    //! STUB (void)scene; (void)x;
    //! STUB return PS_TODO("lesson 06: contribution", DColor(0.0));
    //! BEGIN
    const size_t k = x.size() - 1;
    if (x.size() < 2 || x[0].sp.light < 0) return DColor(0.0);
    const Light& light = scene.lights[size_t(x[0].sp.light)];
    DColor f(light.kind == LightKind::Area ? emittedRadiance(light, x[0].sp.n, direction(x[0], x[1])) : light.Le);
    for (size_t i = 0; i < k && f != DColor(0.0); ++i) {
        if (!visible(scene, x[i], x[i + 1])) return DColor(0.0);
        f *= double(geometryTerm(x[i], x[i + 1]));
    }
    for (size_t i = 1; i < k && f != DColor(0.0); ++i) {
        const Material& m = scene.materials[size_t(x[i].sp.material)];
        const Vec3 wLight = direction(x[i], x[i - 1]), wCamera = direction(x[i], x[i + 1]);
        if (x[i].specular) {
            const DeltaLobe lobe = deltaLobe(m, x[i].sp.n, wLight, wCamera, deltaTolerance(x[i - 1], x[i], x[i + 1]));
            f *= lobe.valid ? DColor(lobe.fs) : DColor(0.0);
        } else {
            f *= DColor(evalBSDF(m, x[i].sp.n, wCamera, wLight));
        }
    }
    const Camera& camera = scene.camera;
    const double We =
        double(camera.width()) * double(camera.height()) * double(camera.We(x[k].p(), direction(x[k], x[k - 1])));
    return f * We;
    //! END
}

}  // namespace ps
