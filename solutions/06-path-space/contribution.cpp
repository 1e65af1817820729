// Lesson 6 — the measurement contribution function f(x) of a path, in three-point form.
// Interface: lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

DColor contribution(const Scene& scene, const Path& x) {
    //! TODO(06) The measurement contribution f(x) of the path for the pixel it lands in (Eq. 6.3, W_e^(j) of Eq. 4.6;
    //!          contribution in paths.h), in double; 0 if k < 1. Pitfalls: evalBSDF in lesson 3's argument order; a
    //!          specular vertex gives its delta's coefficient (Eq. 6.11), found with deltaTolerance of the three
    //!          vertices (paths.h: far from the origin the positions round the directions past the default).
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
