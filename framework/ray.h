// Rays and the record of a ray's closest hit.
#pragma once
#include <cstdint>
#include "vecmath.h"

namespace ps {

constexpr uint32_t kNoPrimitive = 0xffffffffu;
// The ignorePrim of a shadow ray that sees nothing without being traced: Scene::occluded says
// true (Scene::spawnRayTo, between a point light on surfaces and a point in one of its planes).
constexpr uint32_t kBlockedRay = 0xfffffffeu;

struct Ray {
    Vec3 o;                              // origin
    Vec3 d;                              // direction, always unit length
    float tMax = kInf;                   // the ray is the open segment (0, tMax)
    uint32_t ignorePrim = kNoPrimitive;  // the flat triangle it leaves: it cannot hit it again
    Ray() = default;
    Ray(const Vec3& o_, const Vec3& d_, float tMax_ = kInf, uint32_t ignore = kNoPrimitive)
        : o(o_), d(d_), tMax(tMax_), ignorePrim(ignore) {}
    Vec3 at(float t) const { return o + t * d; }
};

// A point on a surface, as the integrators see it.
struct SurfacePoint {
    Vec3 p;                        // position
    Vec3 n;                        // unit geometric normal (triangles: by winding; spheres: outward)
    float errScale = 0.0f;         // magnitude of the coordinates p was computed from (ray offsets)
    uint32_t prim = kNoPrimitive;  // index into Scene::prims
    int material = -1;             // index into Scene::materials
    int light = -1;                // index into Scene::lights, -1 if the surface does not emit
};

// Moves p off its surface along +-n (the side w points to), by a few float ulps of the
// coordinates the hit was computed from. Relative, never absolute: it works the same for a
// scene at scale 1e-4 and one translated by 1e5. (errScale = 0 gives no offset.)
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& n, float errScale, const Vec3& w) {
    float eps = errScale * 0x1p-19f;  // ~16 ulps of the largest coordinate involved
    return glm::dot(n, w) >= 0.0f ? p + eps * n : p - eps * n;
}

}  // namespace ps
