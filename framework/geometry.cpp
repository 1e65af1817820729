#include "geometry.h"

namespace ps {

WatertightRay::WatertightRay(const Ray& ray) {
    // kz: the dimension where the direction is largest; kx, ky the other two, swapped to keep
    // the winding when d[kz] < 0.
    Vec3 a = glm::abs(ray.d);
    kz = (a.x > a.y) ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (ray.d[kz] < 0.0f) std::swap(kx, ky);
    Sx = ray.d[kx] / ray.d[kz];
    Sy = ray.d[ky] / ray.d[kz];
    Sz = 1.0f / ray.d[kz];
}

bool intersectTriangle(const Ray& ray, const WatertightRay& wr, const Triangle& tri,
                       float& t, float& b1, float& b2) {
    // Vertices relative to the ray origin, sheared so the ray is the +z axis.
    const Vec3 A = tri.p0 - ray.o, B = tri.p1 - ray.o, C = tri.p2 - ray.o;
    const float Ax = A[wr.kx] - wr.Sx * A[wr.kz], Ay = A[wr.ky] - wr.Sy * A[wr.kz];
    const float Bx = B[wr.kx] - wr.Sx * B[wr.kz], By = B[wr.ky] - wr.Sy * B[wr.kz];
    const float Cx = C[wr.kx] - wr.Sx * C[wr.kz], Cy = C[wr.ky] - wr.Sy * C[wr.kz];
    // Scaled barycentric coordinates (2D edge functions).
    float U = Cx * By - Cy * Bx;
    float V = Ax * Cy - Ay * Cx;
    float W = Bx * Ay - By * Ax;
    // On an edge, recompute in double so the sign is exact.
    if (U == 0.0f || V == 0.0f || W == 0.0f) {
        U = static_cast<float>(double(Cx) * double(By) - double(Cy) * double(Bx));
        V = static_cast<float>(double(Ax) * double(Cy) - double(Ay) * double(Cx));
        W = static_cast<float>(double(Bx) * double(Ay) - double(By) * double(Ax));
    }
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return false;
    const float det = U + V + W;
    if (det == 0.0f) return false;
    // Scaled hit distance, compared without a division.
    const float Az = wr.Sz * A[wr.kz], Bz = wr.Sz * B[wr.kz], Cz = wr.Sz * C[wr.kz];
    const float T = U * Az + V * Bz + W * Cz;
    if (det < 0.0f ? (T >= 0.0f || T < ray.tMax * det) : (T <= 0.0f || T > ray.tMax * det))
        return false;
    const float invDet = 1.0f / det;
    t = T * invDet;
    if (!(t > 0.0f && t < ray.tMax)) return false;
    b1 = V * invDet;
    b2 = W * invDet;
    return true;
}

bool intersectSphere(const Ray& ray, const Sphere& s, float& t) {
    const Vec3 f = ray.o - s.center;
    const float b = glm::dot(f, ray.d);             // half the linear coefficient (|d| = 1)
    const Vec3 l = f - b * ray.d;                   // closest approach, computed directly
    const float r2 = s.radius * s.radius;
    const float disc = r2 - glm::dot(l, l);         // Hearn & Baker: no catastrophic cancellation
    if (disc < 0.0f) return false;
    const float c = glm::dot(f, f) - r2;
    const float q = -b - std::copysign(std::sqrt(disc), b);
    float t0 = (q != 0.0f) ? c / q : 0.0f;
    float t1 = q;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0.0f && t0 < ray.tMax) { t = t0; return true; }
    if (t1 > 0.0f && t1 < ray.tMax) { t = t1; return true; }
    return false;
}

}  // namespace ps
