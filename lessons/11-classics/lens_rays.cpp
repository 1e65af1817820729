// Lesson 11 — plumbing (nothing to write here): hands the thin lens's rays to the framework, whose
// pixel loop makes every camera-ray algorithm's rays (framework/tasks.h, cameraRay). The framework
// is built before the lessons, so it cannot call Camera::lensPoint and Camera::lensRay itself: this
// registration, at start-up, tells it how. Interface: lessons/11-classics/thinlens.h.
#include "11-classics/thinlens.h"

namespace ps {

namespace {
Ray lensRays(const Camera& camera, const Vec2& raster, const Vec2& uLens) {
    return camera.lensRay(raster, camera.lensPoint(uLens));
}
[[maybe_unused]] const bool registered = Camera::setLensRays(&lensRays);
}  // namespace

}  // namespace ps
