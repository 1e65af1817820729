// Lesson 11 — the thin lens: its points, rays, raster positions, importance and densities.
// Interface: lessons/11-classics/thinlens.h (ThinLens; eye_, forward_, right_, up_ are the
// pinhole camera's frame, pinhole_ the pinhole camera itself).
// Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/thinlens.h"
#include "todo.h"
#include "warps.h"

namespace ps {

Vec3 ThinLens::lensPoint(const Vec2& u) const {
    //! TODO(11) A uniform point on the lens (Eq. 11.10; thinlens.h). Pitfall (README 6): scale lesson 1's unit disk.
    //! STUB (void)u;
    //! STUB return PS_TODO("lesson 11: ThinLens::lensPoint", eye_);
    //! BEGIN
    const Vec2 d = sampleConcentricDisk(u);
    return eye_ + lensRadius_ * (d.x * right_ + d.y * up_);
    //! END
}

float ThinLens::pdfLens() const {
    //! TODO(11) The density of lensPoint's points per unit area on the lens (Eq. 11.11).
    //! STUB return PS_TODO("lesson 11: ThinLens::pdfLens", 0.0f);
    //! BEGIN
    return 1.0f / (kPi * lensRadius_ * lensRadius_);
    //! END
}

Ray ThinLens::lensRay(const Vec2& raster, const Vec3& z) const {
    //! TODO(11) The lens ray from z through raster (Eq. 11.12; thinlens.h), unit direction. Pitfall (README 6): the
    //!          plane of focus is a plane at depth focus_ along forward_, not a sphere.
    //! STUB (void)raster; (void)z;
    //! STUB return PS_TODO("lesson 11: ThinLens::lensRay", Ray(eye_, forward_));
    //! BEGIN
    const Vec3 d = pinhole_.generateRay(raster).d;
    const Vec3 p = eye_ + d * (focus_ / glm::dot(d, forward_));
    return Ray(z, glm::normalize(p - z));
    //! END
}

bool ThinLens::lensRasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const {
    //! TODO(11) The raster position of the ray (z, dir) (Eq. 11.13; thinlens.h). Pitfalls: the pinhole's test of the
    //!          same direction is wrong near the borders (README 6); a point far from the origin loses precision unless
    //!          taken relative to eye_.
    //! STUB (void)z; (void)dir; (void)raster;
    //! STUB return PS_TODO("lesson 11: ThinLens::lensRasterOfDirection", false);
    //! BEGIN
    const float depth = glm::dot(dir, forward_);
    if (!(depth > 0.0f)) return false;
    return pinhole_.rasterOfDirection((z - eye_) + dir * (focus_ / depth), raster);
    //! END
}

float ThinLens::lensWe(const Vec3& z, const Vec3& dir) const {
    //! TODO(11) W_e(z, dir), normalised over the lens and the image (Eq. 11.14); 0 outside the image by the lens's own
    //!          raster test. Pitfalls (README 6): the lens's 1 / (pi r^2); the powers of cos theta.
    //! STUB (void)z; (void)dir;
    //! STUB return PS_TODO("lesson 11: ThinLens::lensWe", 0.0f);
    //! BEGIN
    const float cosTheta = glm::dot(dir, forward_);
    Vec2 landing;
    if (!(cosTheta > 0.0f) || !lensRasterOfDirection(z, dir, landing)) return 0.0f;
    const float c2 = cosTheta * cosTheta;
    return pdfLens() / (pinhole_.imagePlaneArea() * c2 * c2);
    //! END
}

float ThinLens::lensPdfDirection(const Vec3& z, const Vec3& dir) const {
    //! TODO(11) The solid-angle density of lensRay's direction at z for a uniform raster position (Eq. 11.15); 0
    //!          outside the image by the lens's raster test.
    //! STUB (void)z; (void)dir;
    //! STUB return PS_TODO("lesson 11: ThinLens::lensPdfDirection", 0.0f);
    //! BEGIN
    const float cosTheta = glm::dot(dir, forward_);
    Vec2 raster;
    if (!(cosTheta > 0.0f) || !lensRasterOfDirection(z, dir, raster)) return 0.0f;
    return 1.0f / (pinhole_.imagePlaneArea() * cosTheta * cosTheta * cosTheta);
    //! END
}

}  // namespace ps
