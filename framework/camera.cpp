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

bool Camera::rasterPosition(const Vec3& p, Vec2& raster) const {
    const Vec3 d = p - eye_;
    const float z = glm::dot(d, forward_);
    if (!(z > 0.0f)) return false;
    const float sx = glm::dot(d, right_) / z, sy = glm::dot(d, up_) / z;
    raster = Vec2((sx / tanHalfX_ + 1.0f) * 0.5f * width_, (1.0f - sy / tanHalfY_) * 0.5f * height_);
    return raster.x >= 0.0f && raster.x < width_ && raster.y >= 0.0f && raster.y < height_;
}

float Camera::We(const Vec3& dir) const {
    const float cosTheta = glm::dot(dir, forward_);
    Vec2 raster;
    if (!(cosTheta > 0.0f) || !rasterPosition(eye_ + dir, raster)) return 0.0f;
    const float c2 = cosTheta * cosTheta;
    return 1.0f / (imagePlaneArea() * c2 * c2);
}

float Camera::pdfDirection(const Vec3& dir) const {
    const float cosTheta = glm::dot(dir, forward_);
    Vec2 raster;
    if (!(cosTheta > 0.0f) || !rasterPosition(eye_ + dir, raster)) return 0.0f;
    return 1.0f / (imagePlaneArea() * cosTheta * cosTheta * cosTheta);
}

}  // namespace ps
