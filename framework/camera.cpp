#include "camera.h"

namespace ps {

Camera::Camera(const Vec3& eye, const Vec3& target, const Vec3& up, float fovY, int width, int height)
    : eye_(eye), width_(width), height_(height) {
    forward_ = glm::normalize(target - eye);
    right_ = glm::normalize(glm::cross(forward_, up));
    up_ = glm::cross(right_, forward_);
    tanHalfY_ = std::tan(0.5f * fovY * kPi / 180.0f);
    tanHalfX_ = tanHalfY_ * static_cast<float>(width) / static_cast<float>(height);
}

namespace {
// Raster position of the direction d (any length) from the pinhole, given the camera's basis;
// false if d points behind the camera or outside the image.
bool rasterOf(const Vec3& d, const Vec3& forward, const Vec3& right, const Vec3& up, float tanHalfX, float tanHalfY,
              int width, int height, Vec2& raster) {
    const float z = glm::dot(d, forward);
    if (!(z > 0.0f)) return false;
    const float sx = glm::dot(d, right) / z, sy = glm::dot(d, up) / z;
    raster = Vec2((sx / tanHalfX + 1.0f) * 0.5f * width, (1.0f - sy / tanHalfY) * 0.5f * height);
    return raster.x >= 0.0f && raster.x < width && raster.y >= 0.0f && raster.y < height;
}
}  // namespace

bool Camera::rasterPosition(const Vec3& p, Vec2& raster) const {
    return rasterOf(p - eye_, forward_, right_, up_, tanHalfX_, tanHalfY_, width_, height_, raster);
}

bool Camera::rasterOfDirection(const Vec3& dir, Vec2& raster) const {
    return rasterOf(dir, forward_, right_, up_, tanHalfX_, tanHalfY_, width_, height_, raster);
}

// Camera::We (the emitted importance) is lesson 4's piece: solutions/04-measurement/importance.cpp.

// The pdf tests the direction itself: eye_ + dir would be rounded to the ulp of the eye's
// coordinates (0.008 at 1e5) and misjudge directions near the image edges.
float Camera::pdfDirection(const Vec3& dir) const {
    const float cosTheta = glm::dot(dir, forward_);
    Vec2 raster;
    if (!(cosTheta > 0.0f) || !rasterOf(dir, forward_, right_, up_, tanHalfX_, tanHalfY_, width_, height_, raster))
        return 0.0f;
    return 1.0f / (imagePlaneArea() * cosTheta * cosTheta * cosTheta);
}

}  // namespace ps
