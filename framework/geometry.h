// The two kinds of shape: triangles (watertight test) and analytic spheres.
#pragma once
#include "ray.h"

namespace ps {

struct AABB {
    Vec3 lo = Vec3(kInf), hi = Vec3(-kInf);
    void expand(const Vec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void expand(const AABB& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x; }
    Vec3 extent() const { return hi - lo; }
    Vec3 center() const { return 0.5f * (lo + hi); }
    float surfaceArea() const {
        if (empty()) return 0.0f;
        Vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

struct Triangle {
    Vec3 p0, p1, p2;  // counter-clockwise seen from the side the normal points to
    Vec3 normal() const { return glm::normalize(glm::cross(p1 - p0, p2 - p0)); }
    float area() const { return 0.5f * glm::length(glm::cross(p1 - p0, p2 - p0)); }
    AABB bounds() const {
        AABB b;
        b.expand(p0);
        b.expand(p1);
        b.expand(p2);
        return b;
    }
    float errScale() const { return std::max(maxAbsComponent(p0), std::max(maxAbsComponent(p1), maxAbsComponent(p2))); }
};

struct Sphere {
    Vec3 center;
    float radius = 1.0f;
    AABB bounds() const {
        AABB b;
        b.expand(center - Vec3(radius));
        b.expand(center + Vec3(radius));
        return b;
    }
    float area() const { return 4.0f * kPi * radius * radius; }
    float errScale() const { return maxAbsComponent(center) + radius; }
};

// Per-ray constants of the watertight test (Woop, Benthin, Wald 2013), computed once per ray.
struct WatertightRay {
    int kx, ky, kz;
    float Sx, Sy, Sz;
    explicit WatertightRay(const Ray& ray);
};

// Watertight ray/triangle test: a ray through a shared edge or vertex hits exactly one side
// (never neither). On a hit in (0, ray.tMax): t and the barycentric weights b1, b2 of p1, p2.
bool intersectTriangle(const Ray& ray, const WatertightRay& wr, const Triangle& tri, float& t, float& b1, float& b2);

// Ray/sphere with the numerically careful quadratic (Hearn & Baker discriminant).
bool intersectSphere(const Ray& ray, const Sphere& s, float& t);

}  // namespace ps
