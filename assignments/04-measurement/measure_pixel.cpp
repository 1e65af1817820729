// Lesson 4 — a pixel measured as <W_e, L>. Interface: lessons/04-measurement/measurement.h.
// Equation numbers refer to lessons/04-measurement/README.md.
#include "04-measurement/measurement.h"
#include "todo.h"

namespace ps {

Color pixelMeasurementSample(const Scene& scene, int px, int py, const Vec3& dir, float pdf, Rng& rng, int maxDepth) {
    // TODO(04) One sample of I_j = <W_e^(j), L> (Eq. 4.7): W = pixelImportance(scene.camera, px,
    //          py, dir); return 0 if W is 0. Otherwise L = LiMIS(scene, Ray(pinhole, dir), rng,
    //          maxDepth) (lesson 3; the pinhole is scene.camera.position()), and the sample is
    //          W * L * cos(theta) / pdf, with cos(theta) = dot(dir, scene.camera.forward()).
    (void)scene; (void)px; (void)py; (void)dir; (void)pdf; (void)rng; (void)maxDepth;
    return PS_TODO("lesson 04: pixelMeasurementSample", Color(0.0f));
}

}  // namespace ps
