// Lesson 11 — the thin lens: its points, rays, raster positions, importance and densities.
// Interface: lessons/11-classics/thinlens.h (ThinLens; eye_, forward_, right_, up_ are the
// pinhole camera's frame, pinhole_ the pinhole camera itself).
// Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/thinlens.h"
#include "todo.h"
#include "warps.h"

namespace ps {

Vec3 ThinLens::lensPoint(const Vec2& u) const {
    // TODO(11) A uniform point on the lens (Eq. 11.10; thinlens.h). Pitfall (README 6): scale lesson 1's unit disk.
    (void)u;
    return PS_TODO("lesson 11: ThinLens::lensPoint", eye_);
}

float ThinLens::pdfLens() const {
    // TODO(11) The density of lensPoint's points per unit area on the lens (Eq. 11.11).
    return PS_TODO("lesson 11: ThinLens::pdfLens", 0.0f);
}

Ray ThinLens::lensRay(const Vec2& raster, const Vec3& z) const {
    // TODO(11) The lens ray from z through raster (Eq. 11.12; thinlens.h), unit direction. Pitfall (README 6): the
    //          plane of focus is a plane at depth focus_ along forward_, not a sphere.
    (void)raster; (void)z;
    return PS_TODO("lesson 11: ThinLens::lensRay", Ray(eye_, forward_));
}

bool ThinLens::lensRasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const {
    // TODO(11) The raster position of the ray (z, dir) (Eq. 11.13; thinlens.h). Pitfalls: the pinhole's test of the
    //          same direction is wrong near the borders (README 6); a point far from the origin loses precision unless
    //          taken relative to eye_.
    (void)z; (void)dir; (void)raster;
    return PS_TODO("lesson 11: ThinLens::lensRasterOfDirection", false);
}

float ThinLens::lensWe(const Vec3& z, const Vec3& dir) const {
    // TODO(11) W_e(z, dir), normalised over the lens and the image (Eq. 11.14); 0 outside the image by the lens's own
    //          raster test. Pitfalls (README 6): the lens's 1 / (pi r^2); the powers of cos theta.
    (void)z; (void)dir;
    return PS_TODO("lesson 11: ThinLens::lensWe", 0.0f);
}

float ThinLens::lensPdfDirection(const Vec3& z, const Vec3& dir) const {
    // TODO(11) The solid-angle density of lensRay's direction at z for a uniform raster position (Eq. 11.15); 0
    //          outside the image by the lens's raster test.
    (void)z; (void)dir;
    return PS_TODO("lesson 11: ThinLens::lensPdfDirection", 0.0f);
}

}  // namespace ps
