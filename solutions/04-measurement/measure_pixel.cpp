// Lesson 4 — a pixel measured as <W_e, L>. Interface: lessons/04-measurement/measurement.h.
// Equation numbers refer to lessons/04-measurement/README.md.
#include "04-measurement/measurement.h"
#include "todo.h"

namespace ps {

Color pixelMeasurementSample(const Scene& scene, int px, int py, const Vec3& dir, float pdf, Rng& rng, int maxDepth) {
    //! TODO(04) One sample of I_j (Eq. 4.7) as measurement.h says. Pitfall: its cosine is against the camera axis.
    //! STUB (void)scene; (void)px; (void)py; (void)dir; (void)pdf; (void)rng; (void)maxDepth;
    //! STUB return PS_TODO("lesson 04: pixelMeasurementSample", Color(0.0f));
    //! BEGIN
    const Camera& camera = scene.camera;
    const float W = pixelImportance(camera, px, py, dir);
    if (W == 0.0f) return Color(0.0f);
    const Color L = LiMIS(scene, Ray(camera.position(), dir), rng, maxDepth);
    return L * (W * glm::dot(dir, camera.forward()) / pdf);
    //! END
}

}  // namespace ps
