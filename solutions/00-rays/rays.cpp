// Lesson 0 — rays: camera rays and the watertight ray/triangle test.
// The interfaces are framework/camera.h (Camera::generateRay) and framework/geometry.h
// (WatertightRay, intersectTriangle); lessons/00-rays/README.md derives the equations.
#include "camera.h"
#include "geometry.h"
#include "todo.h"

namespace ps {

Ray Camera::generateRay(const Vec2& raster) const {
    //! TODO(00) Map the raster position to the image plane at distance 1 (Eq. 0.1) and
    //!          return the ray from the pinhole eye_ through it, direction normalised (Eq. 0.2).
    //!          Members: eye_, forward_, right_, up_, tanHalfX_, tanHalfY_, width_, height_.
    //! STUB (void)raster;
    //! STUB return PS_TODO("lesson 00: Camera::generateRay", Ray(eye_, forward_));
    //! BEGIN
    const float sx = (2.0f * raster.x / width_ - 1.0f) * tanHalfX_;
    const float sy = (1.0f - 2.0f * raster.y / height_) * tanHalfY_;
    return Ray(eye_, glm::normalize(forward_ + sx * right_ + sy * up_));
    //! END
}

WatertightRay::WatertightRay(const Ray& ray) {
    //! TODO(00) Choose kz, the axis where |d| is largest, and kx, ky the next two (swap them
    //!          when d[kz] < 0 to keep the winding), then the shear constants Sx, Sy, Sz (Eq. 0.3).
    //! STUB kx = 0; ky = 1; kz = 2; Sx = 0.0f; Sy = 0.0f; Sz = 1.0f; (void)ray;
    //! BEGIN
    const Vec3 a = glm::abs(ray.d);
    kz = (a.x > a.y) ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (ray.d[kz] < 0.0f) std::swap(kx, ky);
    Sx = ray.d[kx] / ray.d[kz];
    Sy = ray.d[ky] / ray.d[kz];
    Sz = 1.0f / ray.d[kz];
    //! END
}

bool intersectTriangle(const Ray& ray, const WatertightRay& wr, const Triangle& tri, float& t, float& b1, float& b2) {
    //! TODO(00) Translate the vertices to the ray origin and shear them (Eq. 0.3); compute the
    //!          edge functions U, V, W (Eq. 0.4), recomputed in double when one is exactly 0;
    //!          reject when their signs differ or det = U + V + W is 0 (Eq. 0.5); compare the
    //!          scaled distance T with 0 and ray.tMax * det without dividing (Eq. 0.6); set t,
    //!          b1 = V / det, b2 = W / det and return true only for 0 < t < ray.tMax.
    //! STUB (void)ray; (void)wr; (void)tri; (void)t; (void)b1; (void)b2;
    //! STUB return PS_TODO("lesson 00: intersectTriangle", false);
    //! BEGIN
    // Vertices relative to the ray origin, sheared so the ray is the +z axis (Eq. 0.3).
    const Vec3 A = tri.p0 - ray.o, B = tri.p1 - ray.o, C = tri.p2 - ray.o;
    // (glm's v[i] is a switch over i, three branches per use; a pointer to the components, as
    // glm::value_ptr gives, reads component i with one load.)
    const float *a = &A.x, *b = &B.x, *c = &C.x;
    const float Ax = a[wr.kx] - wr.Sx * a[wr.kz], Ay = a[wr.ky] - wr.Sy * a[wr.kz];
    const float Bx = b[wr.kx] - wr.Sx * b[wr.kz], By = b[wr.ky] - wr.Sy * b[wr.kz];
    const float Cx = c[wr.kx] - wr.Sx * c[wr.kz], Cy = c[wr.ky] - wr.Sy * c[wr.kz];
    // Scaled barycentric coordinates: 2D edge functions (Eq. 0.4).
    float U = Cx * By - Cy * Bx;
    float V = Ax * Cy - Ay * Cx;
    float W = Bx * Ay - By * Ax;
    // On an edge, recompute in double so that the sign is exact.
    if (U == 0.0f || V == 0.0f || W == 0.0f) {
        U = static_cast<float>(double(Cx) * double(By) - double(Cy) * double(Bx));
        V = static_cast<float>(double(Ax) * double(Cy) - double(Ay) * double(Cx));
        W = static_cast<float>(double(Bx) * double(Ay) - double(By) * double(Ax));
    }
    // Inside only if U, V, W do not have different signs (Eq. 0.5).
    if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return false;
    const float det = U + V + W;
    if (det == 0.0f) return false;
    // Scaled hit distance, compared with (0, tMax) without a division (Eq. 0.6).
    const float Az = wr.Sz * a[wr.kz], Bz = wr.Sz * b[wr.kz], Cz = wr.Sz * c[wr.kz];
    const float T = U * Az + V * Bz + W * Cz;
    if (det < 0.0f ? (T >= 0.0f || T < ray.tMax * det) : (T <= 0.0f || T > ray.tMax * det)) return false;
    const float invDet = 1.0f / det;
    t = T * invDet;
    if (!(t > 0.0f && t < ray.tMax)) return false;
    b1 = V * invDet;
    b2 = W * invDet;
    return true;
    //! END
}

}  // namespace ps
