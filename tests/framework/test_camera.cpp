// Tests of framework/camera.h: the pinhole camera's rays, raster positions and direction pdf.
// (The emitted importance W_e is lesson 4's piece: tests/04-measurement tests it.)
#include <doctest/doctest.h>
#include <cmath>
#include <functional>
#include <vector>
#include "camera.h"

using namespace ps;

namespace {

struct CameraCase {
    const char* name;
    Vec3 eye, target, up;
    float fov;
    int w, h;
};
const CameraCase kCameras[] = {
    {"fov 40, 64x48, looking down +z", Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 64, 48},
    {"fov 120, 160x90, oblique", Vec3(1, 2, 3), Vec3(4, -1, 5), Vec3(0, 0, 1), 120.0f, 160, 90},
    {"fov 25, 33x101 (tall, odd)", Vec3(-2, 0.5f, 7), Vec3(-2.5f, 0.25f, -3), Vec3(0.2f, 1, 0), 25.0f, 33, 101},
};
Camera make(const CameraCase& c) { return Camera(c.eye, c.target, c.up, c.fov, c.w, c.h); }

// The camera's image plane at distance 1, recovered from generateRay alone: forward, the unit
// vectors along +x (right) and -y (up) of the raster, and the half-extents tanHalfX, tanHalfY.
struct ImagePlane {
    glm::dvec3 f, r, u;
    double tx, ty;
    // Unit direction through the image-plane point (sx, sy) (sx right, sy up).
    glm::dvec3 dir(double sx, double sy) const { return glm::normalize(f + sx * r + sy * u); }
};
ImagePlane planeOf(const Camera& cam) {
    ImagePlane p;
    p.f = glm::dvec3(cam.forward());
    const glm::dvec3 dr(cam.generateRay(Vec2(float(cam.width()), 0.5f * cam.height())).d);
    const glm::dvec3 du(cam.generateRay(Vec2(0.5f * cam.width(), 0.0f)).d);
    const glm::dvec3 rr = dr / glm::dot(dr, p.f) - p.f, uu = du / glm::dot(du, p.f) - p.f;  // on the plane z = 1
    p.tx = glm::length(rr);
    p.ty = glm::length(uu);
    p.r = rr / p.tx;
    p.u = uu / p.ty;
    return p;
}

// Solid angle of the spherical triangle (a, b, c), unit vectors (Van Oosterom & Strackee 1983):
// tan(Omega / 2) = |a . (b x c)| / (1 + a.b + b.c + c.a).
double triangleSolidAngle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const double num = std::abs(glm::dot(a, glm::cross(b, c)));
    const double den = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
    return 2.0 * std::atan2(num, den);
}
// Solid angle seen through the image-plane rectangle [x0, x1] x [y0, y1].
double rectSolidAngle(const ImagePlane& p, double x0, double y0, double x1, double y1) {
    const glm::dvec3 a = p.dir(x0, y0), b = p.dir(x1, y0), c = p.dir(x1, y1), d = p.dir(x0, y1);
    return triangleSolidAngle(a, b, c) + triangleSolidAngle(a, c, d);
}

// Integral of g(direction) over the directions through the image-plane rectangle
// [x0, x1] x [y0, y1], on an n x n grid: sum of g(cell centre) * (exact solid angle of the cell).
double integrateOverRect(const ImagePlane& p, double x0, double y0, double x1, double y1, int n,
                         const std::function<double(const Vec3&)>& g) {
    double sum = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double xa = x0 + (x1 - x0) * i / n, xb = x0 + (x1 - x0) * (i + 1) / n;
            const double ya = y0 + (y1 - y0) * j / n, yb = y0 + (y1 - y0) * (j + 1) / n;
            sum += g(Vec3(p.dir(0.5 * (xa + xb), 0.5 * (ya + yb)))) * rectSolidAngle(p, xa, ya, xb, yb);
        }
    return sum;
}

// Image-plane coordinates of raster position (x, y) (y grows downward).
glm::dvec2 planeOfRaster(const ImagePlane& p, const Camera& cam, double x, double y) {
    return {(2.0 * x / cam.width() - 1.0) * p.tx, (1.0 - 2.0 * y / cam.height()) * p.ty};
}

}  // namespace

TEST_CASE("camera: rasterPosition of a point on generateRay's ray gives back the raster position") {
    // Tolerance 1e-3 px: float rounding of the direction (~1e-7) over a pixel of ~1e-2 radians
    // is ~1e-5 px; 1e-3 leaves room for the point p = o + t d being rounded at t = 1e4.
    for (const CameraCase& cc : kCameras) {
        const Camera cam = make(cc);
        const float W = float(cc.w), H = float(cc.h);
        const Vec2 rasters[] = {Vec2(0.5f * W, 0.5f * H),
                                Vec2(0.5f, 0.5f),
                                Vec2(W - 0.5f, H - 0.5f),
                                Vec2(W - 0.5f, 0.5f),
                                Vec2(0.5f, H - 0.5f),
                                Vec2(0.0f, 0.0f),
                                Vec2(W, H),
                                Vec2(0.0f, H),
                                Vec2(0.3f, 0.7f * H),
                                Vec2(W - 1e-3f, 1e-3f)};
        for (const Vec2& x : rasters) {
            const Ray ray = cam.generateRay(x);
            CHECK(std::abs(glm::length(ray.d) - 1.0f) < 1e-6f);
            CHECK(ray.o == cc.eye);
            for (float t : {1.0f, 100.0f, 1e4f}) {
                Vec2 back(-1.0f);
                const bool inside = cam.rasterPosition(ray.at(t), back);
                INFO(cc.name << ": raster (" << x.x << ", " << x.y << "), point at t = " << t);
                CHECK_MESSAGE(glm::length(back - x) < 1e-3f,
                              "expected (" << x.x << ", " << x.y << "), got (" << back.x << ", " << back.y << ")");
                const bool interior = x.x >= 1e-2f && x.y >= 1e-2f && x.x <= W - 1e-2f && x.y <= H - 1e-2f;
                if (interior) CHECK_MESSAGE(inside, "expected rasterPosition to report the point inside the image");
            }
        }
    }
}

TEST_CASE("camera: points behind the camera, in its plane, or outside the image give false") {
    for (const CameraCase& cc : kCameras) {
        const Camera cam = make(cc);
        const ImagePlane p = planeOf(cam);
        const Vec3 eye = cc.eye, f = cam.forward(), r(p.r), u(p.u);
        Vec2 raster;
        INFO(cc.name);
        CHECK_FALSE(cam.rasterPosition(eye - 5.0f * f, raster));  // straight behind
        CHECK_FALSE(cam.rasterPosition(eye - 5.0f * f + 0.1f * r + 0.1f * u, raster));
        CHECK_FALSE(cam.rasterPosition(eye + 3.0f * r, raster));  // in the camera's plane
        CHECK_FALSE(cam.rasterPosition(eye, raster));             // the pinhole itself
        // Just outside each image edge (1 % beyond the half-extent), at distance 10.
        const float tx = float(p.tx), ty = float(p.ty);
        CHECK_FALSE(cam.rasterPosition(eye + 10.0f * (f + 1.01f * tx * r), raster));
        CHECK_FALSE(cam.rasterPosition(eye + 10.0f * (f - 1.01f * tx * r), raster));
        CHECK_FALSE(cam.rasterPosition(eye + 10.0f * (f + 1.01f * ty * u), raster));
        CHECK_FALSE(cam.rasterPosition(eye + 10.0f * (f - 1.01f * ty * u), raster));
        CHECK(cam.rasterPosition(eye + 10.0f * (f + 0.99f * tx * r + 0.99f * ty * u), raster));
        // The pdf is 0 there too, and rasterOfDirection agrees with rasterPosition.
        CHECK(cam.pdfDirection(-f) == 0.0f);
        CHECK(cam.pdfDirection(glm::normalize(f - 1.01f * ty * u)) == 0.0f);
        CHECK_FALSE(cam.rasterOfDirection(-f, raster));
        CHECK_FALSE(cam.rasterOfDirection(f + 1.01f * tx * r, raster));
        CHECK(cam.rasterOfDirection(f + 0.99f * tx * r + 0.99f * ty * u, raster));
    }
}

TEST_CASE("camera: pdfDirection integrates to 1 over the image's directions") {
    // Integrated over a rectangle 1.25 times the image in each direction, so the zero outside
    // is tested too; the image edges fall on cell edges (grid of 500: the edges at cells 50 and
    // 450). Each cell's solid angle is exact (spherical triangles), the integrand is taken at
    // the cell centre: midpoint error O(h^2) ~ (1/200)^2. Tolerance 1e-3.
    for (const CameraCase& cc : kCameras) {
        const Camera cam = make(cc);
        const ImagePlane p = planeOf(cam);
        const double X = 1.25 * p.tx, Y = 1.25 * p.ty;
        const double iPdf = integrateOverRect(p, -X, -Y, X, Y, 500, [&](const Vec3& d) { return cam.pdfDirection(d); });
        INFO(cc.name);
        CHECK_MESSAGE(std::abs(iPdf - 1.0) < 1e-3, "integral of pdfDirection over the image: expected 1, got " << iPdf);
        CHECK(cam.imagePlaneArea() == doctest::Approx(4.0 * p.tx * p.ty).epsilon(1e-5));
    }
}

TEST_CASE("camera: pdfDirection is the density of rays through uniform raster positions") {
    // A raster cell of delta x delta pixels around x has probability delta^2 / (w h) under
    // uniform raster sampling and subtends the solid angle Omega (exact): the density of
    // directions there is delta^2 / (w h Omega). delta = 0.01 px; tolerance 1e-3 relative
    // (the density varies by ~delta/w across the cell).
    for (const CameraCase& cc : kCameras) {
        const Camera cam = make(cc);
        const ImagePlane p = planeOf(cam);
        const double delta = 0.01;
        for (const Vec2& x : {Vec2(0.5f * cc.w, 0.5f * cc.h), Vec2(0.5f, 0.5f), Vec2(cc.w - 0.5f, 0.5f),
                              Vec2(0.3f * cc.w, 0.8f * cc.h)}) {
            const glm::dvec2 a = planeOfRaster(p, cam, x.x - 0.5 * delta, x.y + 0.5 * delta);
            const glm::dvec2 b = planeOfRaster(p, cam, x.x + 0.5 * delta, x.y - 0.5 * delta);
            const double omega = rectSolidAngle(p, a.x, a.y, b.x, b.y);
            const double expect = delta * delta / (double(cc.w) * cc.h * omega);
            const float got = cam.pdfDirection(cam.generateRay(x).d);
            CHECK_MESSAGE(std::abs(got - expect) < 1e-3 * expect, cc.name << " at raster (" << x.x << ", " << x.y
                                                                          << "): expected pdf " << expect << ", got "
                                                                          << got);
        }
    }
}

TEST_CASE("camera: pdfDirection and rasterOfDirection do not depend on where the camera is") {
    // The same camera at the origin and translated by 1e5: pdfDirection(dir) and
    // rasterOfDirection(dir) are functions of the direction alone, so directions half a pixel
    // inside every image edge must give the same, nonzero pdf (relative 1e-5) and the same raster
    // position. Rounding eye + dir at 1e5 (ulp 0.008) would move such a direction by ~3 pixels of
    // this 256 x 256 image and drop it.
    const Camera near(Vec3(0), Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 256, 256);
    const Vec3 shift(1e5f, -1e5f, 1e5f);
    const Camera far(shift, shift + Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 256, 256);
    int bad = 0;
    for (int k = 0; k < 256; ++k) {
        const float c = k + 0.5f;
        for (const Vec2& x : {Vec2(0.5f, c), Vec2(255.5f, c), Vec2(c, 0.5f), Vec2(c, 255.5f), Vec2(c, c)}) {
            const Vec3 d = near.generateRay(x).d;
            const float pdf = near.pdfDirection(d), pdfFar = far.pdfDirection(d);
            Vec2 r(-1.0f), rFar(-2.0f);
            const bool in = near.rasterOfDirection(d, r), inFar = far.rasterOfDirection(d, rFar);
            const bool ok = pdf > 0.0f && std::abs(pdfFar - pdf) <= 1e-5f * pdf && in && inFar && r == rFar &&
                            glm::length(r - x) < 1e-3f;
            if (!ok && ++bad <= 5)
                FAIL_CHECK("raster (" << x.x << ", " << x.y << "): pdf " << pdf << " at the origin, " << pdfFar
                                      << " translated by 1e5; rasterOfDirection (" << r.x << ", " << r.y << ") vs ("
                                      << rFar.x << ", " << rFar.y << ")");
        }
    }
    CHECK_MESSAGE(bad == 0, "expected 0 directions to differ, got " << bad);
}
