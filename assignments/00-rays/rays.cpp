// Lesson 0 — rays: camera rays and the watertight ray/triangle test.
// The interfaces are framework/camera.h (Camera::generateRay) and framework/geometry.h
// (WatertightRay, intersectTriangle); lessons/00-rays/README.md derives the equations.
#include "camera.h"
#include "geometry.h"
#include "todo.h"

namespace ps {

Ray Camera::generateRay(const Vec2& raster) const {
    // TODO(00) Map the raster position to the image plane at distance 1 (Eq. 0.1) and
    //          return the ray from the pinhole eye_ through it, direction normalised (Eq. 0.2).
    //          Members: eye_, forward_, right_, up_, tanHalfX_, tanHalfY_, width_, height_.
    (void)raster;
    return PS_TODO("lesson 00: Camera::generateRay", Ray(eye_, forward_));
}

WatertightRay::WatertightRay(const Ray& ray) {
    // TODO(00) Choose kz, the axis where |d| is largest, and kx, ky the next two (swap them
    //          when d[kz] < 0 to keep the winding), then the shear constants Sx, Sy, Sz (Eq. 0.3).
    kx = 0; ky = 1; kz = 2; Sx = 0.0f; Sy = 0.0f; Sz = 1.0f; (void)ray;
}

bool intersectTriangle(const Ray& ray, const WatertightRay& wr, const Triangle& tri, float& t, float& b1, float& b2) {
    // TODO(00) Translate the vertices to the ray origin and shear them (Eq. 0.3); compute the
    //          edge functions U, V, W (Eq. 0.4), recomputed in double when one is exactly 0;
    //          reject when their signs differ or det = U + V + W is 0 (Eq. 0.5); compare the
    //          scaled distance T with 0 and ray.tMax * det without dividing (Eq. 0.6); set t,
    //          b1 = V / det, b2 = W / det and return true only for 0 < t < ray.tMax.
    (void)ray; (void)wr; (void)tri; (void)t; (void)b1; (void)b2;
    return PS_TODO("lesson 00: intersectTriangle", false);
}

}  // namespace ps
