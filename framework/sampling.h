// Sampling helpers the framework's materials and lights use. (Lesson 1 derives these warps;
// the student's versions live in the lesson, these are the framework's own.)
#pragma once
#include <vector>
#include "math.h"

namespace ps {

// Cosine-weighted direction about +z: pdf = cos(theta) / pi (Malley's method).
inline Vec3 sampleCosineHemisphere(const Vec2& u) {
    float r = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x)));
}
inline float cosineHemispherePdf(float cosTheta) { return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f; }

// Uniform direction on the unit sphere: pdf = 1 / (4 pi).
inline Vec3 sampleUniformSphere(const Vec2& u) {
    float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}
constexpr float kUniformSpherePdf = 1.0f / (4.0f * kPi);

// Direction about +z with pdf (n + 1) / (2 pi) cos^n(alpha) (the Phong lobe).
inline Vec3 samplePhongLobe(const Vec2& u, float exponent) {
    float c = std::pow(1.0f - u.x, 1.0f / (exponent + 1.0f));   // 1 - u.x in (0, 1]
    float s = std::sqrt(std::max(0.0f, 1.0f - c * c)), phi = 2.0f * kPi * u.y;
    return Vec3(s * std::cos(phi), s * std::sin(phi), c);
}
inline float phongLobePdf(float cosAlpha, float exponent) {
    return cosAlpha > 0.0f ? (exponent + 1.0f) * (0.5f * kInvPi) * std::pow(cosAlpha, exponent) : 0.0f;
}

// Uniform point on a triangle: barycentrics (b1, b2) of p1, p2 (Heitz 2019, low distortion).
inline Vec2 sampleUniformTriangle(const Vec2& u) {
    float b0, b1;
    if (u.x < u.y) { b0 = u.x / 2; b1 = u.y - b0; }
    else { b1 = u.y / 2; b0 = u.x - b1; }
    return Vec2(b1, 1.0f - b0 - b1);
}

// A discrete distribution over n weights (light selection by power, triangles by area).
class Distribution1D {
public:
    Distribution1D() = default;
    explicit Distribution1D(const std::vector<double>& weights) {
        cdf_.assign(weights.size() + 1, 0.0);
        for (size_t i = 0; i < weights.size(); ++i) cdf_[i + 1] = cdf_[i] + std::max(0.0, weights[i]);
        total_ = cdf_.back();
        if (total_ > 0.0) for (double& c : cdf_) c /= total_;
    }
    size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
    double total() const { return total_; }
    // Picks index i with probability w_i / sum w; u in [0, 1).
    size_t sample(float u) const {
        size_t lo = 0, hi = size();   // find i with cdf[i] <= u < cdf[i+1]
        while (hi - lo > 1) { size_t mid = (lo + hi) / 2; (cdf_[mid] <= u ? lo : hi) = mid; }
        return lo;
    }
    float pmf(size_t i) const { return i < size() ? static_cast<float>(cdf_[i + 1] - cdf_[i]) : 0.0f; }

private:
    std::vector<double> cdf_;
    double total_ = 0.0;
};

}  // namespace ps
