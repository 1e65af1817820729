// Lesson 11 — the thin lens: its points, rays, raster positions, importance and densities.
// Interface: lessons/11-classics/thinlens.h (ThinLens; eye_, forward_, right_, up_ are the
// pinhole camera's frame, pinhole_ the pinhole camera itself).
// Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/thinlens.h"
#include "todo.h"
#include "warps.h"

namespace ps {

Vec3 ThinLens::lensPoint(const Vec2& u) const {
    //! TODO(11) Eq. 11.10: a uniform point on the lens, the disk of radius lensRadius_ about eye_
    //!          spanned by right_ and up_: d = sampleConcentricDisk(u) (lesson 1), then
    //!          z = eye_ + lensRadius_ (d.x right_ + d.y up_).
    //!          Pitfall: the unit disk's point scaled by the lens radius.
    //! STUB (void)u;
    //! STUB return PS_TODO("lesson 11: ThinLens::lensPoint", eye_);
    //! BEGIN
    const Vec2 d = sampleConcentricDisk(u);
    return eye_ + lensRadius_ * (d.x * right_ + d.y * up_);
    //! END
}

float ThinLens::pdfLens() const {
    //! TODO(11) Eq. 11.11: the density of lensPoint's points per unit area on the lens.
    //! STUB return PS_TODO("lesson 11: ThinLens::pdfLens", 0.0f);
    //! BEGIN
    return 1.0f / (kPi * lensRadius_ * lensRadius_);
    //! END
}

Ray ThinLens::lensRay(const Vec2& raster, const Vec3& z) const {
    //! TODO(11) Eq. 11.12: the pinhole's ray through raster (pinhole_.generateRay, lesson 0) meets the
    //!          plane of focus, at DEPTH focus_ along forward_, in the point of focus
    //!          p = eye_ + d focus_ / dot(d, forward_); the lens ray leaves z towards p
    //!          (direction normalised).
    //!          Pitfall: the plane of focus is a plane, not a sphere: eye_ + focus_ d (focus_
    //!          along the ray) is sharp only in the image's centre.
    //! STUB (void)raster; (void)z;
    //! STUB return PS_TODO("lesson 11: ThinLens::lensRay", Ray(eye_, forward_));
    //! BEGIN
    const Vec3 d = pinhole_.generateRay(raster).d;
    const Vec3 p = eye_ + d * (focus_ / glm::dot(d, forward_));
    return Ray(z, glm::normalize(p - z));
    //! END
}

bool ThinLens::lensRasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const {
    //! TODO(11) Eq. 11.13: the ray (z, dir) (dir of any length) meets the plane of focus in
    //!          p = z + dir focus_ / dot(dir, forward_) (z lies in the lens plane, at depth 0);
    //!          its raster position is the pinhole's of p: pinhole_.rasterOfDirection(p - eye_, raster).
    //!          False if dir does not point in front of the lens (dot(dir, forward_) <= 0).
    //!          Pitfall: rasterOfDirection(p - eye_), not rasterPosition(p): eye_ + ... rounds far
    //!          from the origin.
    //! STUB (void)z; (void)dir; (void)raster;
    //! STUB return PS_TODO("lesson 11: ThinLens::lensRasterOfDirection", false);
    //! BEGIN
    const float depth = glm::dot(dir, forward_);
    if (!(depth > 0.0f)) return false;
    return pinhole_.rasterOfDirection((z - eye_) + dir * (focus_ / depth), raster);
    //! END
}

float ThinLens::lensWe(const Vec3& z, const Vec3& dir) const {
    //! TODO(11) Eq. 11.14: W_e(z, dir) = 1 / (pi r^2 A cos^4 theta) when the ray (z, dir) lands in
    //!          the image (lensRasterOfDirection), else 0; A = pinhole_.imagePlaneArea(), cos(theta) =
    //!          dot(dir, forward_) (dir unit). Then W_e cos(theta) integrates to 1 over the lens
    //!          and the image's directions from each of its points.
    //!          Pitfalls: the 1 / (pi r^2) of the lens (pdfLens()); cos^4: one cosine for the
    //!          lens's projected area, three for the solid angle of an image element.
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
    //! TODO(11) Eq. 11.15: the solid-angle density of lensRay's direction at z when raster is
    //!          uniform on the image: 1 / (A cos^3 theta) where the ray (z, dir) lands in the
    //!          image, else 0 (as the pinhole's pdfDirection, but with the lens's raster position).
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
