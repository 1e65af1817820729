// A pinhole camera that generates rays and answers what bidirectional methods ask of it:
// the emitted importance W_e, the solid-angle pdf of its rays, the raster position of a point.
#pragma once
#include "ray.h"

namespace ps {

class Camera {
public:
    Camera() = default;
    // fovY: full vertical field of view in degrees, 0 < fovY < 180.
    Camera(const Vec3& eye, const Vec3& target, const Vec3& up, float fovY, int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }
    const Vec3& position() const { return eye_; }
    const Vec3& forward() const { return forward_; }
    bool isPinhole() const { return true; }  // a delta position: rays cannot hit the lens

    // Ray through raster position (x, y) in [0, width) x [0, height); y grows downward.
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

private:
    Vec3 eye_, forward_ = Vec3(0, 0, 1), right_ = Vec3(1, 0, 0), up_ = Vec3(0, 1, 0);
    float tanHalfX_ = 1.0f, tanHalfY_ = 1.0f;
    int width_ = 1, height_ = 1;
};

}  // namespace ps
