// Lesson 5 — connecting a vertex to the pinhole camera. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

CameraConnection connectToCamera(const Scene& scene, const SurfacePoint& y, bool onSurface, const Vec3& z) {
    // TODO(05) What connecting y to the camera point z gives (Eq. 5.3, 5.5), as lighttracer.h and README 2 say (a
    //          camera model's z: framework/camera.h). Pitfalls (README 6): W_e of the direction from the eye; a cosine
    //          at a y on no surface; a shadow ray that offsets the pinhole.
    (void)scene; (void)y; (void)onSurface; (void)z;
    return PS_TODO("lesson 05: connectToCamera", CameraConnection());
}

}  // namespace ps
