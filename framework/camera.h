// The camera: a pinhole, or a thin lens of radius lensRadius() focused at focusDistance()
// (lesson 11). It generates rays and answers what bidirectional methods ask of it: the emitted
// importance W_e, the densities of its rays, the raster position of a point.
#pragma once
#include "ray.h"
#include "rng.h"

namespace ps {

class Camera {
public:
    Camera() = default;
    // fovY: full vertical field of view in degrees, 0 < fovY < 180. lensRadius 0: a pinhole;
    // lensRadius > 0: a thin lens in the plane through eye perpendicular to the view, sharp at
    // the plane focusDistance in front of it (lesson 11, Eq. 11.10-11.15).
    Camera(const Vec3& eye, const Vec3& target, const Vec3& up, float fovY, int width, int height,
           float lensRadius = 0.0f, float focusDistance = 1.0f);

    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& position() const { return eye_; }  // the pinhole, or the centre of the lens
    const Vec3& forward() const { return forward_; }
    const Vec3& right() const { return right_; }  // the raster's +x on the image plane
    const Vec3& up() const { return up_; }        // the raster's -y on the image plane
    float lensRadius() const { return lensRadius_; }
    float focusDistance() const { return focus_; }
    // A pinhole is a delta position: rays cannot hit it. A thin lens is a disk they can hit.
    bool isPinhole() const { return lensRadius_ == 0.0f; }
    int line = 0;  // the scene file line of the camera (for messages), 0 if none

    // ---- the pinhole -------------------------------------------------------------------------

    // Ray through raster position (x, y) in [0, width) x [0, height); y grows downward.
    // Lesson 0's piece (solutions/00-rays/rays.cpp). The pinhole's ray, also for a thin lens.
    Ray generateRay(const Vec2& raster) const;

    // Raster position where the direction from the pinhole towards p crosses the image;
    // false if p is behind the camera or outside the image.
    bool rasterPosition(const Vec3& p, Vec2& raster) const;
    // The same for a direction dir (any length) leaving the pinhole. Prefer it to
    // rasterPosition(position() + dir): adding dir to a far-off eye rounds it.
    bool rasterOfDirection(const Vec3& dir, Vec2& raster) const;

    // Importance emitted along dir (unit, from the pinhole), normalised over the whole image:
    // W_e = 1 / (A cos^4 theta) inside the image, 0 outside, where A is the area of the image
    // rectangle at distance 1. Then the integral of W_e cos(theta) over the image's directions
    // is 1. A single pixel's sensor is W_e * width * height restricted to that pixel.
    // Lesson 4's piece: implemented in solutions/04-measurement/importance.cpp (reference) or
    // assignments/04-measurement/importance.cpp (yours), not in camera.cpp.
    float We(const Vec3& dir) const;

    // Solid-angle pdf of dir for rays through uniformly chosen raster positions:
    // pdf = 1 / (A cos^3 theta) (0 outside the image).
    float pdfDirection(const Vec3& dir) const;

    // Area of the image rectangle at distance 1 from the pinhole.
    float imagePlaneArea() const { return 4.0f * tanHalfX_ * tanHalfY_; }

    // ---- the thin lens: lesson 11's pieces (solutions/11-classics/thinlens.cpp, Eq. 11.10-11.15),
    // for lensRadius() > 0 only. A lens point z lies on the disk of radius lensRadius() about
    // position() spanned by right() and up(); dir is a unit direction leaving z. ----------------

    // The lens point for u in [0, 1)^2: uniform on the lens, by lesson 1's concentric map (Eq. 11.10).
    Vec3 lensPoint(const Vec2& u) const;
    // Its density per unit area on the lens (Eq. 11.11).
    float pdfLens() const;
    // The ray from lens point z through raster position `raster`: towards the point of the plane
    // of focus that the pinhole's ray through `raster` meets (Eq. 11.12).
    Ray lensRay(const Vec2& raster, const Vec3& z) const;
    // Raster position of the ray (z, dir): where its point on the plane of focus is seen from the
    // lens centre; false if dir points behind the lens or the position is outside the image (Eq. 11.13).
    bool lensRasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const;
    // Importance W_e(z, dir) emitted by lens point z along dir, normalised over the lens and the
    // whole image (Eq. 11.14); 0 outside the image.
    float lensWe(const Vec3& z, const Vec3& dir) const;
    // Solid-angle pdf of dir at z for rays through uniformly chosen raster positions (Eq. 11.15).
    float lensPdfDirection(const Vec3& z, const Vec3& dir) const;

    // ---- the camera point z of a path: the pinhole, or a point on the lens -------------------
    // Lessons 5-7 ask these, so that one piece of code serves both cameras; for a pinhole each
    // is exactly the pinhole's function above (z is position(), uLens is not used).

    // The camera point for lens sample uLens, and its density: 1 for the pinhole (a delta
    // position, chosen with probability 1), pdfLens() per unit area on a lens.
    Vec3 samplePoint(const Vec2& uLens) const { return isPinhole() ? eye_ : lensPoint(uLens); }
    float pdfPoint() const { return isPinhole() ? 1.0f : pdfLens(); }
    // The pinhole's point, or a lens point drawn with the next two numbers of rng (none for a pinhole).
    Vec3 samplePoint(Rng& rng) const { return isPinhole() ? eye_ : lensPoint(rng.uniform2()); }
    // The ray from camera point z through raster position `raster`.
    Ray generateRay(const Vec2& raster, const Vec3& z) const {
        return isPinhole() ? generateRay(raster) : lensRay(raster, z);
    }
    // Where the point p, seen from camera point z, lands on the image.
    bool rasterPosition(const Vec3& z, const Vec3& p, Vec2& raster) const {
        return isPinhole() ? rasterPosition(p, raster) : lensRasterOfDirection(z, p - z, raster);
    }
    // W_e(z, dir) and the solid-angle pdf of dir at z.
    float We(const Vec3& z, const Vec3& dir) const { return isPinhole() ? We(dir) : lensWe(z, dir); }
    float pdfDirection(const Vec3& z, const Vec3& dir) const {
        return isPinhole() ? pdfDirection(dir) : lensPdfDirection(z, dir);
    }

    // Where a ray meets the lens from the front (travelling against forward()): the distance t in
    // (0, ray.tMax) and the point z on the lens disk. False for a pinhole. (Geometry, not a piece.)
    bool hitLens(const Ray& ray, float& t, Vec3& z) const;

    // ---- camera rays for the framework's pixel loop ------------------------------------------
    // The ray through raster position `raster` and, for a thin lens, the lens point of uLens.
    // The framework is built before lesson 11: the lesson's plumbing hands it the lens's rays at
    // start-up (setLensRays). A program without lesson 11 renders pinholes only (render() refuses
    // a lens camera then: lensRaysAvailable()).
    Ray sampleRay(const Vec2& raster, const Vec2& uLens) const;
    using LensRays = Ray (*)(const Camera& camera, const Vec2& raster, const Vec2& uLens);
    static bool setLensRays(LensRays rays);
    static bool lensRaysAvailable();

private:
    Vec3 eye_, forward_ = Vec3(0, 0, 1), right_ = Vec3(1, 0, 0), up_ = Vec3(0, 1, 0);
    float tanHalfX_ = 1.0f, tanHalfY_ = 1.0f;
    int width_ = 1, height_ = 1;
    float lensRadius_ = 0.0f, focus_ = 1.0f;
};

}  // namespace ps
