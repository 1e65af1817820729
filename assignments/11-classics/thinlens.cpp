// Lesson 11 — the thin lens: its points, rays, raster positions, importance and densities.
// Interface: framework/camera.h (the Camera members below) and lessons/11-classics/thinlens.h.
// Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/thinlens.h"
#include "todo.h"
#include "warps.h"

namespace ps {

Vec3 Camera::lensPoint(const Vec2& u) const {
    // TODO(11) Eq. 11.10: a uniform point on the lens, the disk of radius lensRadius_ about eye_
    //          spanned by right_ and up_: d = sampleConcentricDisk(u) (lesson 1), then
    //          z = eye_ + lensRadius_ (d.x right_ + d.y up_).
    //          Pitfall: the unit disk's point scaled by the lens radius.
    (void)u;
    return PS_TODO("lesson 11: Camera::lensPoint", eye_);
}

float Camera::pdfLens() const {
    // TODO(11) Eq. 11.11: the density of lensPoint's points per unit area on the lens.
    return PS_TODO("lesson 11: Camera::pdfLens", 0.0f);
}

Ray Camera::lensRay(const Vec2& raster, const Vec3& z) const {
    // TODO(11) Eq. 11.12: the pinhole's ray through raster (generateRay, lesson 0) meets the
    //          plane of focus, at DEPTH focus_ along forward_, in the point of focus
    //          p = eye_ + d focus_ / dot(d, forward_); the lens ray leaves z towards p
    //          (direction normalised).
    //          Pitfall: the plane of focus is a plane, not a sphere: eye_ + focus_ d (focus_
    //          along the ray) is sharp only in the image's centre.
    (void)raster; (void)z;
    return PS_TODO("lesson 11: Camera::lensRay", Ray(eye_, forward_));
}

bool Camera::lensRasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const {
    // TODO(11) Eq. 11.13: the ray (z, dir) (dir of any length) meets the plane of focus in
    //          p = z + dir focus_ / dot(dir, forward_) (z lies in the lens plane, at depth 0);
    //          its raster position is the pinhole's of p: rasterOfDirection(p - eye_, raster).
    //          False if dir does not point in front of the lens (dot(dir, forward_) <= 0).
    //          Pitfall: rasterOfDirection(p - eye_), not rasterPosition(p): eye_ + ... rounds far
    //          from the origin.
    (void)z; (void)dir; (void)raster;
    return PS_TODO("lesson 11: Camera::lensRasterOfDirection", false);
}

float Camera::lensWe(const Vec3& z, const Vec3& dir) const {
    // TODO(11) Eq. 11.14: W_e(z, dir) = 1 / (pi r^2 A cos^4 theta) when the ray (z, dir) lands in
    //          the image (lensRasterOfDirection), else 0; A = imagePlaneArea(), cos(theta) =
    //          dot(dir, forward_) (dir unit). Then W_e cos(theta) integrates to 1 over the lens
    //          and the image's directions from each of its points.
    //          Pitfalls: the 1 / (pi r^2) of the lens (pdfLens()); cos^4: one cosine for the
    //          lens's projected area, three for the solid angle of an image element.
    (void)z; (void)dir;
    return PS_TODO("lesson 11: Camera::lensWe", 0.0f);
}

float Camera::lensPdfDirection(const Vec3& z, const Vec3& dir) const {
    // TODO(11) Eq. 11.15: the solid-angle density of lensRay's direction at z when raster is
    //          uniform on the image: 1 / (A cos^3 theta) where the ray (z, dir) lands in the
    //          image, else 0 (as the pinhole's pdfDirection, but with the lens's raster position).
    (void)z; (void)dir;
    return PS_TODO("lesson 11: Camera::lensPdfDirection", 0.0f);
}

}  // namespace ps
