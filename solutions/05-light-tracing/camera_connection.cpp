// Lesson 5 — connecting a vertex to the pinhole camera. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

CameraConnection connectToCamera(const Scene& scene, const SurfacePoint& y, bool onSurface, const Vec3& z) {
    //! TODO(05) What connecting y to the camera point z gives (Eq. 5.3, 5.5), as lighttracer.h and README 2 say (a
    //!          camera model's z: framework/camera.h). Pitfalls (README 6): W_e of the direction from the eye; a cosine
    //!          at a y on no surface; a shadow ray that offsets the pinhole.
    //! STUB (void)scene; (void)y; (void)onSurface; (void)z;
    //! STUB return PS_TODO("lesson 05: connectToCamera", CameraConnection());
    //! BEGIN
    CameraConnection c;
    const Camera& camera = scene.camera;
    const Vec3& e = z;
    if (!camera.rasterPosition(e, y.p, c.raster)) return c;
    const Vec3 toEye = e - y.p;
    const float d2 = glm::dot(toEye, toEye), d = std::sqrt(d2);
    if (!(d2 > 0.0f)) return c;
    c.wCam = toEye / d;
    const float W = static_cast<float>(camera.width()) * static_cast<float>(camera.height()) * camera.We(e, -c.wCam);
    if (W <= 0.0f) return c;
    if (scene.occluded(scene.spawnRayTo(y, e))) return c;
    const float cosE = glm::dot(camera.forward(), -c.wCam);
    const float cosY = onSurface ? std::abs(glm::dot(y.n, c.wCam)) : 1.0f;
    c.importance = W * cosE * cosY / (d2 * camera.pdfPoint());
    c.valid = true;
    return c;
    //! END
}

}  // namespace ps
