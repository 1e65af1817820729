// Lesson 5 — connecting a vertex to the pinhole camera. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

CameraConnection connectToCamera(const Scene& scene, const SurfacePoint& y, bool onSurface, const Vec3& z) {
    //! TODO(05) The connection of y to the pinhole e = z (= camera.position(); a camera model's
    //!          point otherwise) (Eq. 5.3, 5.5):
    //!          1. raster: camera.rasterPosition(e, y.p, raster); invalid if false.
    //!          2. d = distance from y to e, wCam = (e - y.p) / d; the direction from the
    //!             pinhole to y is -wCam. W = the pixel's sensor there (lesson 4, Eq. 4.6):
    //!             width * height * camera.We(e, -wCam); invalid if 0.
    //!          3. Invalid if scene.occluded(scene.spawnRayTo(y, e)).
    //!          4. importance = W cos(theta_e) |cos(theta_y)| / (d^2 p), with cos(theta_e) =
    //!             dot(camera.forward(), -wCam), |cos(theta_y)| = |dot(y.n, wCam)| only if
    //!             onSurface (else 1) and p = camera.pdfPoint(), the density of e (1 for the
    //!             pinhole, chosen with probability 1); valid = true.
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
