// Lesson 4 — the emitted importance of the pinhole camera and of one pixel. Interfaces:
// framework/camera.h (Camera::We) and lessons/04-measurement/measurement.h (pixelImportance).
// Equation numbers refer to lessons/04-measurement/README.md.
#include "04-measurement/measurement.h"
#include "todo.h"

namespace ps {

float Camera::We(const Vec3& dir) const {
    //! TODO(04) The whole image's W_e(dir) (Eq. 4.5), 0 behind the camera or off the image. Pitfalls (README 6): cos^3;
    //!          testing position() + dir.
    //! STUB (void)dir;
    //! STUB return PS_TODO("lesson 04: Camera::We", 0.0f);
    //! BEGIN
    const float cosTheta = glm::dot(dir, forward_);
    Vec2 raster;
    if (!(cosTheta > 0.0f) || !rasterOfDirection(dir, raster)) return 0.0f;
    const float c2 = cosTheta * cosTheta;
    return 1.0f / (imagePlaneArea() * c2 * c2);
    //! END
}

float pixelImportance(const Camera& camera, int px, int py, const Vec3& dir) {
    //! TODO(04) W_e^(j)(dir) of Eq. 4.6 (measurement.h); pixel (px, py) is a half-open square of raster positions.
    //! STUB (void)camera; (void)px; (void)py; (void)dir;
    //! STUB return PS_TODO("lesson 04: pixelImportance", 0.0f);
    //! BEGIN
    Vec2 raster;
    if (!camera.rasterOfDirection(dir, raster)) return 0.0f;
    if (static_cast<int>(raster.x) != px || static_cast<int>(raster.y) != py) return 0.0f;
    return static_cast<float>(camera.width()) * static_cast<float>(camera.height()) * camera.We(dir);
    //! END
}

}  // namespace ps
