// Math on GLM: float geometry, float colors per sample, double accumulation (Film).
#pragma once
#include <glm/glm.hpp>
#include <algorithm>
#include <cmath>
#include <limits>

namespace ps {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Color = glm::vec3;    // linear RGB radiance / throughput of one sample
using DColor = glm::dvec3;  // accumulated over many samples

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 1.0f / kPi;
constexpr float kInf = std::numeric_limits<float>::infinity();

inline float maxComponent(const Vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
inline float maxAbsComponent(const Vec3& v) { return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z))); }
inline float luminance(const Color& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }
inline bool isBlack(const Color& c) { return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f; }
inline bool isFinite(const Color& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }
inline bool hasNaN(const Color& c) { return std::isnan(c.r) || std::isnan(c.g) || std::isnan(c.b); }

// Orthonormal frame around a unit normal n (Duff et al. 2017, branchless).
// Local coordinates: z is the normal, so cos(theta) = local.z.
struct Frame {
    Vec3 s, t, n;
    Frame() : s(1, 0, 0), t(0, 1, 0), n(0, 0, 1) {}
    explicit Frame(const Vec3& normal) : n(normal) {
        float sign = std::copysign(1.0f, n.z);
        float a = -1.0f / (sign + n.z);
        float b = n.x * n.y * a;
        s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        t = Vec3(b, sign + n.y * n.y * a, -n.y);
    }
    Vec3 toLocal(const Vec3& v) const { return Vec3(glm::dot(v, s), glm::dot(v, t), glm::dot(v, n)); }
    Vec3 toWorld(const Vec3& v) const { return s * v.x + t * v.y + n * v.z; }
};

// Mirror direction of w about the unit normal n (both pointing away from the surface).
inline Vec3 reflect(const Vec3& w, const Vec3& n) { return 2.0f * glm::dot(w, n) * n - w; }

}  // namespace ps
