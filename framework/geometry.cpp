#include "geometry.h"

namespace ps {

bool intersectSphere(const Ray& ray, const Sphere& s, float& t) {
    const Vec3 f = ray.o - s.center;
    const float b = glm::dot(f, ray.d);  // half the linear coefficient (|d| = 1)
    const Vec3 l = f - b * ray.d;        // closest approach, computed directly
    const float r2 = s.radius * s.radius;
    const float disc = r2 - glm::dot(l, l);  // Hearn & Baker: no catastrophic cancellation
    if (disc < 0.0f) return false;
    const float c = glm::dot(f, f) - r2;
    const float q = -b - std::copysign(std::sqrt(disc), b);
    float t0 = (q != 0.0f) ? c / q : 0.0f;
    float t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0.0f && t0 < ray.tMax) {
        t = t0;
        return true;
    }
    if (t1 > 0.0f && t1 < ray.tMax) {
        t = t1;
        return true;
    }
    return false;
}

}  // namespace ps
