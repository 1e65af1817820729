// Lesson 0, graded: Camera::generateRay (Eq. 0.1 and 0.2 of lessons/00-rays/README.md).
// Every expected direction is computed in double from the camera's parameters (eye, target,
// up, fovY, width, height) with the basis of framework/camera.h; a float implementation must
// match it to kDirTol = 2e-6 per component.
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <vector>
#include "lesson00.h"
#include "seed.h"

using namespace lesson00;
using ps::Camera;

namespace {

// A spread of cameras: square and non-square, wide and narrow, odd sizes, the Cornell box's.
std::vector<CameraSpec> cameras() {
    return {
        {Vec3(278, 273, -800), Vec3(278, 273, -799), Vec3(0, 1, 0), 39.3f, 256, 256},  // scenes/cornell-box.scene
        {Vec3(0, 0, 0), Vec3(0, 0, -1), Vec3(0, 1, 0), 90.0f, 64, 64},
        {Vec3(1, 2, 3), Vec3(-2, 0.5f, 4), Vec3(0, 0, 1), 60.0f, 320, 180},
        {Vec3(-5, 0.25f, 7), Vec3(3, -1, 2), Vec3(0.25f, 1, 0.5f), 10.0f, 90, 160},
        {Vec3(0.5f, -0.5f, 0.5f), Vec3(0.5f, 1.5f, 0.5f), Vec3(1, 0, 1), 150.0f, 7, 5},
        {Vec3(10, 10, 10), Vec3(0, 0, 0), Vec3(0, 1, 0), 30.0f, 1, 1},
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 0), 1.0f, 1000, 10},  // a strip: 1 deg high, 82 deg wide
    };
}

// Checks the ray of camera c through raster (x, y): origin = eye, exact direction. Returns
// false on a mismatch (printed if among the first of the test). `what` names the raster point.
bool checkRay(const CameraSpec& c, const Camera& cam, float x, float y, const std::string& what, Tally& tally) {
    const Ray ray = cam.generateRay(Vec2(x, y));
    const DVec3 expected = exactDirection(c, x, y);
    const double err = maxDiff(ray.d, expected);
    const bool ok = err <= kDirTol && ray.o == c.eye;
    if (tally.fail(ok))
        FAIL_CHECK(c.describe() << "\n  raster (" << x << ", " << y << ") = " << what << "\n  expected ray origin "
                                << str(c.eye) << " direction " << str(expected) << "\n  got      ray origin "
                                << str(ray.o) << " direction " << str(ray.d) << "  (largest component error " << err
                                << ", tolerance " << kDirTol << ")");
    return ok;
}

}  // namespace

TEST_CASE("rays: the primary ray through the image centre is the view direction and off-centre rays are not [1 pt]") {
    Tally tally;
    for (const CameraSpec& c : cameras()) {
        const Camera cam = c.make();
        const float W = float(c.width), H = float(c.height);
        // The centre (W/2, H/2) maps to the image plane's origin: the direction is forward.
        checkRay(c, cam, 0.5f * W, 0.5f * H, "the image centre (expected: the view direction)", tally);
        // Points a quarter of the image away from the centre must turn away from it by the
        // exact amount: right, down, and up-left of the centre.
        checkRay(c, cam, 0.75f * W, 0.5f * H, "right of the centre", tally);
        checkRay(c, cam, 0.5f * W, 0.75f * H, "below the centre (y grows downward)", tally);
        checkRay(c, cam, 0.25f * W, 0.25f * H, "up and left of the centre", tally);
    }
    LESSON00_SUMMARY(tally, "camera rays");
}

TEST_CASE("rays: rays through the corners of the image and of its corner pixels are exact [2 pts]") {
    // (0, 0) is the top-left corner of the image (y grows downward); the other three corners
    // lie on the open side of [0, W) x [0, H), so they are approached to 1/1024 of a pixel.
    const float e = 1.0f / 1024.0f;
    Tally tally;
    for (const CameraSpec& c : cameras()) {
        const Camera cam = c.make();
        const float W = float(c.width), H = float(c.height);
        checkRay(c, cam, 0.0f, 0.0f, "top-left corner of the image", tally);
        checkRay(c, cam, W - e, 0.0f, "top-right corner of the image", tally);
        checkRay(c, cam, 0.0f, H - e, "bottom-left corner of the image", tally);
        checkRay(c, cam, W - e, H - e, "bottom-right corner of the image", tally);
        checkRay(c, cam, 0.5f, 0.5f, "centre of the top-left pixel", tally);
        checkRay(c, cam, W - 0.5f, 0.5f, "centre of the top-right pixel", tally);
        checkRay(c, cam, 0.5f, H - 0.5f, "centre of the bottom-left pixel", tally);
        checkRay(c, cam, W - 0.5f, H - 0.5f, "centre of the bottom-right pixel", tally);
    }
    LESSON00_SUMMARY(tally, "camera rays");
}

TEST_CASE(
    "rays: rays through the midpoints of the image edges make half the field of view with the view direction [1 pt]") {
    // The top edge's midpoint (W/2, 0) lies fovY/2 above the view direction; the left edge's
    // midpoint (0, H/2) lies atan(tan(fovY/2) W/H) to its left.
    Tally tally;
    for (const CameraSpec& c : cameras()) {
        const Camera cam = c.make();
        const float W = float(c.width), H = float(c.height);
        const ExactBasis b = exactBasis(c);
        const double halfY = 0.5 * double(c.fovY) * 3.14159265358979323846 / 180.0;
        const double halfX = std::atan(b.tanX);  // the horizontal field follows from the aspect ratio
        struct Edge {
            float x, y;
            double angle;
            DVec3 side;
            std::string name;
        };
        const Edge edges[] = {{0.5f * W, 0.0f, halfY, b.u, "top edge midpoint (raster y = 0 is the top row)"},
                              {0.0f, 0.5f * H, halfX, -b.r, "left edge midpoint (raster x = 0 is the left column)"}};
        for (const Edge& ed : edges) {
            checkRay(c, cam, ed.x, ed.y, ed.name, tally);
            const DVec3 d(cam.generateRay(Vec2(ed.x, ed.y)).d);
            // The angle to the view direction, and the side of it the ray lies on.
            const double angle = std::atan2(glm::length(glm::cross(d, b.f)), glm::dot(d, b.f));
            const bool ok = std::abs(angle - ed.angle) < 2e-6 && glm::dot(d, ed.side) > 0.0;
            if (tally.fail(ok))
                FAIL_CHECK(c.describe() << "\n  " << ed.name << ": expected a ray "
                                        << ed.angle * 180.0 / 3.14159265358979323846
                                        << " deg from the view direction, towards "
                                        << std::string(ed.x == 0.0f ? "the left" : "the top")
                                        << " of the image\n  got the direction " << str(d) << ", "
                                        << angle * 180.0 / 3.14159265358979323846 << " deg from the view direction, "
                                        << std::string(glm::dot(d, ed.side) > 0.0 ? "on the right side"
                                                                                  : "on the WRONG side"));
        }
    }
    LESSON00_SUMMARY(tally, "rays and angles");
}

TEST_CASE("rays: non-square images take the horizontal field from the aspect ratio and have square pixels [1 pt]") {
    const std::vector<CameraSpec> specs = {
        {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 45.0f, 320, 180},
        {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 45.0f, 180, 320},
        {Vec3(2, -1, 0.5f), Vec3(-3, 4, 1), Vec3(0, 0, 1), 5.0f, 1000, 10},
        {Vec3(2, -1, 0.5f), Vec3(-3, 4, 1), Vec3(0, 0, 1), 20.0f, 3, 700},
    };
    Tally tally;
    for (const CameraSpec& c : specs) {
        const Camera cam = c.make();
        const ExactBasis b = exactBasis(c);
        // Pixel centres along the image's diagonal, every one exact.
        for (int i = 0; i < 8; ++i) {
            const float x = std::floor(i * c.width / 8.0f) + 0.5f, y = std::floor(i * c.height / 8.0f) + 0.5f;
            checkRay(c, cam, x, y, "a pixel centre on the image's diagonal", tally);
        }
        // Square pixels: one pixel step right and one pixel step down move the point on the image
        // plane at distance 1 by the same length, 2 tan(fovY/2) / height.
        const float cx = 0.5f * c.width, cy = 0.5f * c.height;
        const float nx = std::min(cx + 1.0f, c.width - 0.5f), ny = std::min(cy + 1.0f, c.height - 0.5f);
        const auto onPlane = [&](float x, float y) {
            const DVec3 d(cam.generateRay(Vec2(x, y)).d);
            return d / glm::dot(d, b.f);
        };
        const DVec3 p = onPlane(cx, cy);
        const double stepX = glm::length(onPlane(nx, cy) - p) / (nx - cx);
        const double stepY = glm::length(onPlane(cx, ny) - p) / (ny - cy);
        const double expected = 2.0 * b.tanY / c.height;
        // 1e-3: the float directions are accurate to ~1e-7, and a step can be as small as 5e-4.
        const bool ok = std::abs(stepX - expected) < 1e-3 * expected && std::abs(stepY - expected) < 1e-3 * expected;
        if (tally.fail(ok))
            FAIL_CHECK(
                c.describe() << "\n  expected one pixel to the right and one pixel down to move the point on the "
                             << "image plane at distance 1 by 2 tan(fovY/2) / height = " << expected << "\n  got "
                             << stepX << " to the right and " << stepY << " down");
    }
    LESSON00_SUMMARY(tally, "rays and pixel steps");
}

TEST_CASE("rays: rays start at the eye and are unit length with the exact direction for random cameras [2 pts]") {
    // Random cameras: eye and target on a grid of 1/16 (so target - eye is exact in float), any
    // up vector not too close to the view direction, fovY in [5, 150] deg, sizes 1 to 2000 with
    // a horizontal field of view below 150 deg too.
    ps::Rng rng(ps::testseed::seed(1));
    Tally tally;
    for (int k = 0; k < 200; ++k) {
        const auto grid16 = [&](float range) {
            return std::round((2.0f * rng.uniform() - 1.0f) * range * 16.0f) / 16.0f;
        };
        CameraSpec c;
        c.eye = Vec3{grid16(100), grid16(100), grid16(100)};
        Vec3 off;
        do off = Vec3{grid16(8), grid16(8), grid16(8)};
        while (glm::length(off) < 0.5f);
        c.target = c.eye + off;
        do {
            const Vec3 dir = randomUnit(rng);  // before the length's number
            c.up = dir * (0.5f + 2.0f * rng.uniform());
        } while (glm::length(glm::cross(glm::normalize(c.up), glm::normalize(off))) < 0.1f);
        c.fovY = 5.0f + 145.0f * rng.uniform();
        do {
            c.width = 1 + int(rng.nextU32() % 2000);
            c.height = 1 + int(rng.nextU32() % 2000);
        } while (std::tan(c.fovY * ps::kPi / 360.0f) * c.width / c.height > 3.7f);
        const Camera cam = c.make();
        for (int j = 0; j < 50; ++j) {
            const float x = rng.uniform() * c.width, y = rng.uniform() * c.height;
            const Ray ray = cam.generateRay(Vec2(x, y));
            const DVec3 expected = exactDirection(c, x, y);
            const double len = glm::length(DVec3(ray.d)), err = maxDiff(ray.d, expected);
            const bool ok = ray.o == c.eye && std::abs(len - 1.0) < 1e-6 && err <= kDirTol;
            if (tally.fail(ok))
                FAIL_CHECK(c.describe() << "\n  raster (" << x << ", " << y << ")"
                                        << "\n  expected origin " << str(c.eye) << ", |d| = 1, direction "
                                        << str(expected) << "\n  got      origin " << str(ray.o) << ", |d| = " << len
                                        << ", direction " << str(ray.d) << " (largest component error " << err << ")");
        }
    }
    LESSON00_SUMMARY(tally, "camera rays");
}

TEST_CASE("rays: generateRay and Camera::rasterPosition are inverse [1 pt]") {
    ps::Rng rng(ps::testseed::seed(2));
    Tally tally;
    for (const CameraSpec& c : cameras()) {
        const Camera cam = c.make();
        // Points far enough that rounding them to float (at |eye| up to 800) moves them by
        // < 1e-6 rad as seen from the eye.
        const float far = 1.0f + ps::maxAbsComponent(c.eye);
        for (int j = 0; j < 500; ++j) {
            // raster -> ray -> a point on it -> rasterPosition: the same raster position (2e-3 px).
            const Vec2 raster{rng.uniform() * c.width, rng.uniform() * c.height};
            const Ray ray = cam.generateRay(raster);
            const float t = far * (1.0f + 10.0f * rng.uniform());
            const Vec3 p = ray.o + t * ray.d;
            Vec2 back(-1.0f);
            const bool inside = cam.rasterPosition(p, back);
            const bool ok = inside && std::abs(back.x - raster.x) < 2e-3f && std::abs(back.y - raster.y) < 2e-3f;
            if (tally.fail(ok))
                FAIL_CHECK(
                    c.describe() << "\n  generateRay(" << str(raster) << ") = " << str(ray) << "\n  its point "
                                 << str(p) << " at t = " << t << ": expected rasterPosition " << str(raster)
                                 << " (to 2e-3 pixels), got "
                                 << (inside ? str(back) : std::string("outside the image or behind the camera")));
            // point -> rasterPosition -> generateRay: the ray points at the point.
            const ExactBasis b = exactBasis(c);
            const double sx = (2.0 * rng.uniform() - 1.0) * b.tanX, sy = (2.0 * rng.uniform() - 1.0) * b.tanY;
            const Vec3 q = Vec3(DVec3(c.eye) + double(t) * (b.f + sx * b.r + sy * b.u));
            Vec2 r2(-1.0f);
            if (!cam.rasterPosition(q, r2)) continue;  // rounded to just outside the image
            const Ray toQ = cam.generateRay(r2);
            const DVec3 expected = glm::normalize(DVec3(q) - DVec3(c.eye));
            const double err = maxDiff(toQ.d, expected);
            if (tally.fail(err <= kDirTol))
                FAIL_CHECK(c.describe() << "\n  the point " << str(q) << " has rasterPosition " << str(r2)
                                        << "\n  expected generateRay of it to point at it: direction " << str(expected)
                                        << "\n  got " << str(toQ) << " (largest component error " << err << ")");
        }
    }
    LESSON00_SUMMARY(tally, "round trips");
}
