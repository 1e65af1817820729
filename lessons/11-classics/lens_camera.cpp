// Lesson 11 — plumbing (nothing to write here): the thin lens as a camera model of the framework
// (framework/camera.h): its frame, the disk's geometry (where a ray meets it), and the registration
// that lets a scene file's camera line select it: `camera ... lens R [focus F]`. Every algorithm
// that asks the camera through its functions of the camera point z then renders the lens.
// Interface: lessons/11-classics/thinlens.h.
#include <cmath>
#include <cstdio>
#include "11-classics/thinlens.h"

namespace ps {

ThinLens::ThinLens(const Camera& pinhole, float radius, float focus)
    : pinhole_(pinhole),
      eye_(pinhole.position()),
      forward_(pinhole.forward()),
      right_(pinhole.right()),
      up_(pinhole.up()),
      lensRadius_(radius),
      focus_(focus) {}

bool ThinLens::hit(const Ray& ray, float& t, Vec3& z) const {
    const float cosD = glm::dot(ray.d, forward_);
    if (!(cosD < 0.0f)) return false;
    const float tHit = glm::dot(eye_ - ray.o, forward_) / cosD;
    if (!(tHit > 0.0f && tHit < ray.tMax)) return false;
    // The offset from the lens centre, projected into the lens plane (rounding leaves a little
    // of it along forward_).
    Vec3 q = (ray.o + tHit * ray.d) - eye_;
    q -= glm::dot(q, forward_) * forward_;
    if (!(glm::dot(q, q) <= lensRadius_ * lensRadius_)) return false;
    t = tHit;
    z = eye_ + q;
    return true;
}

std::string ThinLens::describe() const {
    char text[64];
    std::snprintf(text, sizeof text, "lens %g focus %g", double(lensRadius_), double(focus_));
    return text;
}

const ThinLens* thinLens(const Camera& camera) { return dynamic_cast<const ThinLens*>(camera.model()); }

namespace {

// A lens must be resolvable where it is and its importance finite with room to spare (issue
// 31: 'lens 2e-19' was accepted; light tracing then gave NaN and Inf, bpt a wrong image):
// - wider than 16 float steps of the eye's coordinates, as a sphere's radius must be: a narrower
//   lens's points round to the eye and its density 1 / (pi r^2) is noise;
// - a pixel's importance through it at the image's corner, w h W_e = w h / (pi r^2 A cos^4)
//   (Eq. 11.14; A the image plane's area at distance 1), below 2^64: float's range is 2^128, and
//   the rest is the path's (its throughput, geometry terms and pdfs multiply it).
void checkLensRadius(const Camera& pinhole, float r, const CameraModelArgs& args) {
    const float at = maxAbsComponent(pinhole.position());
    const float step = std::nextafter(at, kInf) - at;
    if (r < 16.0f * step)
        args.fail("'lens' radius " + args.text("lens") + " is below 16 float steps (" + std::to_string(step) +
                  ") of the eye's coordinates: float cannot resolve such a lens there (it is a pinhole: leave "
                  "'lens' out, or scale the scene)");
    const double w = pinhole.width(), h = pinhole.height(), A = pinhole.imagePlaneArea();
    const double ty = std::sqrt(A * h / (4.0 * w)), tx = ty * w / h;  // A = 4 tx ty, tx / ty = w / h
    const double corner = 1.0 + tx * tx + ty * ty;                    // 1 / cos^2 at the image's corner
    const double importance = w * h * corner * corner / (double(kPi) * r * r * A);
    if (!(importance < 0x1p64)) {
        char value[32];
        std::snprintf(value, sizeof value, "%.3g", importance);
        args.fail("'lens' radius " + args.text("lens") +
                  ": a pixel's importance through so small a lens, w h / (pi r^2 A cos^4) = " + value +
                  ", is beyond 2^64, where float products of transport overflow (scale the scene up)");
    }
}

// `lens R [focus F]`: radius 0 is the pinhole; the plane of focus defaults to the target's
// distance. pi r^2 and its inverse must be normal floats (W_e divides by it), and the lens
// resolvable (checkLensRadius).
std::shared_ptr<const CameraModel> makeThinLens(const Camera& pinhole, const CameraModelArgs& args) {
    const float lens = args.number("lens", 0.0f);
    if (lens < 0.0f) args.fail("'lens' (the lens radius) must not be negative, got " + args.text("lens"));
    if (lens > 0.0f && !(std::isnormal(kPi * lens * lens) && std::isnormal(1.0f / (kPi * lens * lens))))
        args.fail("'lens' radius " + args.text("lens") +
                  ": pi r^2 or its inverse leaves float's normal range (scale the scene's units)");
    if (lens > 0.0f) checkLensRadius(pinhole, lens, args);
    if (args.has("focus") && !args.has("lens"))
        args.fail("'focus' without 'lens RADIUS': a pinhole is sharp at every distance");
    const float focus = args.number("focus", args.targetDistance);
    if (!(focus > 0.0f && std::isfinite(focus)))
        args.fail("'focus' (the distance of the plane of focus) must be positive and finite");
    if (lens == 0.0f) return nullptr;
    return std::make_shared<ThinLens>(pinhole, lens, focus);
}

[[maybe_unused]] const bool registered =
    Registry<CameraModelType>::add("lens", CameraModelType{{{"lens", 1}, {"focus", 1}}, makeThinLens});

}  // namespace

}  // namespace ps
