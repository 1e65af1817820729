// Lesson 4 — the emitted importance of the pinhole camera and of one pixel. Interfaces:
// framework/camera.h (Camera::We) and lessons/04-measurement/measurement.h (pixelImportance).
// Equation numbers refer to lessons/04-measurement/README.md.
#include "04-measurement/measurement.h"
#include "todo.h"

namespace ps {

float Camera::We(const Vec3& dir) const {
    // TODO(04) The whole image's W_e(dir) (Eq. 4.5), 0 behind the camera or off the image. Pitfalls (README 6): cos^3;
    //          testing position() + dir.
    (void)dir;
    return PS_TODO("lesson 04: Camera::We", 0.0f);
}

float pixelImportance(const Camera& camera, int px, int py, const Vec3& dir) {
    // TODO(04) W_e^(j)(dir) of Eq. 4.6 (measurement.h); pixel (px, py) is a half-open square of raster positions.
    (void)camera; (void)px; (void)py; (void)dir;
    return PS_TODO("lesson 04: pixelImportance", 0.0f);
}

}  // namespace ps
