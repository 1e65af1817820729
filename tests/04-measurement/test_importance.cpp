// Lesson 4, graded: the emitted importance of the pinhole camera (Eq. 4.5) and of one pixel
// (Eq. 4.6), by deterministic quadrature over the image plane: each cell's solid angle is exact
// (spherical triangles), the integrand is taken at the cell centre (midpoint error ~ h^2).
#include "lesson04.h"

using namespace lesson04;

TEST_CASE("measurement: W_e cos integrates to 1 over the image and is 0 outside it (Eq. 4.5) [2 pts]") {
    // The integral over a rectangle 1.25 times the image in each direction (so the zero outside
    // counts too; grid of 500 with the image edges on cell edges): 1 within 1e-3. At the centre
    // W_e = 1/A exactly (relative 1e-5); behind the camera and just outside each edge 0; and
    // W_e is a function of the direction alone: the same camera translated by 1e5 gives the same
    // values half a pixel inside every image edge (eye + dir rounded at 1e5 would not).
    for (const CameraCase& cc : kCameras) {
        const ps::Camera cam = cc.make();
        const ImagePlane p = planeOf(cam);
        const Vec3 f = cam.forward();
        const double X = 1.25 * p.tx, Y = 1.25 * p.ty, A = 4.0 * p.tx * p.ty;
        const double I =
            integrateOverRect(p, -X, -Y, X, Y, 500, [&](const Vec3& d) { return cam.We(d) * glm::dot(d, f); });
        CHECK_MESSAGE(std::abs(I - 1.0) < 1e-3,
                      cc.name << ": integral of W_e cos(theta) over the image: expected 1, got " << num(I));
        const float centre = cam.We(f);
        CHECK_MESSAGE(std::abs(centre * A - 1.0) < 1e-5, cc.name
                                                             << ": W_e along the axis: expected 1/A = " << num(1.0 / A)
                                                             << " (A = image area at distance 1), got " << num(centre));
        const Vec3 r(p.r), u(p.u);
        const float tx = float(p.tx), ty = float(p.ty);
        for (const Vec3& d : {-f, glm::normalize(f + 1.01f * tx * r), glm::normalize(f - 1.01f * tx * r),
                              glm::normalize(f + 1.01f * ty * u), glm::normalize(f - 1.01f * ty * u),
                              glm::normalize(f + 1.01f * tx * r + 1.01f * ty * u), glm::normalize(r)}) {
            const float we = cam.We(d);
            CHECK_MESSAGE(we == 0.0f,
                          cc.name << ": direction " << str(d) << " is outside the image: expected W_e 0, got " << we);
        }
    }
    const ps::Camera near(Vec3(0), Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 256, 256);
    const Vec3 shift(1e5f, -1e5f, 1e5f);
    const ps::Camera far(shift, shift + Vec3(0, 0, 1), Vec3(0, 1, 0), 40.0f, 256, 256);
    int bad = 0;
    for (int k = 0; k < 256; ++k) {
        const float c = k + 0.5f;
        for (const Vec2& x : {Vec2(0.5f, c), Vec2(255.5f, c), Vec2(c, 0.5f), Vec2(c, 255.5f)}) {
            const Vec3 d = near.generateRay(x).d;
            const float we = near.We(d), weFar = far.We(d);
            if (!(we > 0.0f && std::abs(weFar - we) <= 1e-5f * we) && ++bad <= 3)
                FAIL_CHECK("raster " << str(x) << ", direction " << str(d) << ": W_e " << we
                                     << " for a camera at the origin, " << weFar
                                     << " for the same camera translated by 1e5: expected equal and > 0");
        }
    }
    CHECK_MESSAGE(bad == 0, "W_e depends on where the camera is: " << bad << " of 1024 directions differ");
}

TEST_CASE(
    "measurement: a pixel's importance integrates to 1 over its directions, centre and corners of a wide-angle image (Eq. 4.6) [3 pts]") {
    // For pixels at the centre and the four corners: the integral of W_e^(j) cos(theta) over the
    // pixel's directions is 1 (32 x 32 cells, tolerance 1e-3), and over the block of 3 x 3 pixels
    // around it still 1 (W_e^(j) is 0 in the neighbours). In the wide-angle image a corner pixel
    // lies 74 degrees off the axis: a wrong power of cos(theta) is off there by a factor 3.6.
    for (const CameraCase& cc : kCameras) {
        const ps::Camera cam = cc.make();
        const ImagePlane p = planeOf(cam);
        const Vec3 f = cam.forward();
        for (const std::pair<int, int>& pixel :
             {std::pair<int, int>{cc.w / 2, cc.h / 2}, {0, 0}, {cc.w - 1, cc.h - 1}, {cc.w - 1, 0}, {0, cc.h - 1}}) {
            const int i = pixel.first,
                      j = pixel.second;  // named, not bound: clang < 16 captures no binding in a lambda
            const auto W = [&](const Vec3& d) { return double(ps::pixelImportance(cam, i, j, d)) * glm::dot(d, f); };
            const glm::dvec2 a = p.ofRaster(i, j + 1.0), b = p.ofRaster(i + 1.0, j);
            const double I = integrateOverRect(p, a.x, a.y, b.x, b.y, 32, W);
            const double cosCentre = glm::dot(p.dir(0.5 * (a.x + b.x), 0.5 * (a.y + b.y)), p.f);
            CHECK_MESSAGE(std::abs(I - 1.0) < 1e-3,
                          cc.name << ", pixel (" << i << ", " << j << ") at "
                                  << num(std::acos(cosCentre) * 180.0 / 3.14159265358979, 4)
                                  << " degrees from the axis: integral of W_e^(j) cos(theta) over the pixel's "
                                     "directions: expected 1, got "
                                  << num(I));
            // The 3 x 3 block (clipped to the image) on a 96 x 96 grid: the pixel edges fall on cell edges.
            const int i0 = std::max(0, i - 1), i1 = std::min(cc.w, i + 2), j0 = std::max(0, j - 1),
                      j1 = std::min(cc.h, j + 2);
            const glm::dvec2 c = p.ofRaster(i0, j1), d = p.ofRaster(i1, j0);
            const double block = integrateOverRect(p, c.x, c.y, d.x, d.y, 96, W);
            CHECK_MESSAGE(std::abs(block - 1.0) < 2e-3,
                          cc.name << ", pixel (" << i << ", " << j
                                  << "): integral of W_e^(j) cos(theta) over the pixel and its neighbours: "
                                     "expected 1 (0 outside the pixel), got "
                                  << num(block));
        }
        // Outside the image: half a pixel beyond the corner pixel (0, 0) (raster (-0.5, -0.5), which a
        // cast to int puts in pixel 0) and straight behind the camera.
        const glm::dvec2 out = p.ofRaster(-0.5, -0.5);
        const Vec3 beyond = Vec3(p.dir(out.x, out.y));
        CHECK_MESSAGE(ps::pixelImportance(cam, 0, 0, beyond) == 0.0f,
                      cc.name << ", pixel (0, 0): a direction half a pixel outside the image (raster (-0.5, -0.5)): "
                                 "expected W_e^(j) = 0, got "
                              << ps::pixelImportance(cam, 0, 0, beyond));
        CHECK_MESSAGE(ps::pixelImportance(cam, cc.w / 2, cc.h / 2, -f) == 0.0f,
                      cc.name << ": a direction behind the camera: expected W_e^(j) = 0");
    }
}

TEST_CASE(
    "measurement: W_e^(j) cos(theta) is the density of the camera's rays in pixel j: the path tracer's weight is 1 (Eq. 4.8) [1 pt]") {
    // Camera rays through uniform raster positions of pixel j have the solid-angle density
    // width * height * pdfDirection (framework/camera.h) inside the pixel, so a pixel's sample
    // W_e^(j) L cos / pdf is L itself: the ratio W_e^(j) cos / (width height pdfDirection) must
    // be 1 (relative 1e-4) everywhere in every pixel. Checked at 7 x 7 raster positions inside
    // each of 6 pixels, for every camera.
    for (const CameraCase& cc : kCameras) {
        const ps::Camera cam = cc.make();
        int bad = 0;
        for (auto [i, j] : {std::pair<int, int>{cc.w / 2, cc.h / 2},
                            {0, 0},
                            {cc.w - 1, cc.h - 1},
                            {cc.w - 1, 0},
                            {3, cc.h / 3},
                            {cc.w / 4, 1}})
            for (int a = 0; a < 7; ++a)
                for (int b = 0; b < 7; ++b) {
                    const Vec2 x(i + 0.02f + 0.16f * a, j + 0.02f + 0.16f * b);
                    const Vec3 d = cam.generateRay(x).d;
                    const double ratio = double(ps::pixelImportance(cam, i, j, d)) * glm::dot(d, cam.forward()) /
                                         (double(cc.w) * cc.h * cam.pdfDirection(d));
                    if (!(std::abs(ratio - 1.0) < 1e-4) && ++bad <= 3)
                        FAIL_CHECK(cc.name << ", pixel (" << i << ", " << j << "), raster " << str(x)
                                           << ": expected W_e^(j) cos / (w h pdfDirection) = 1, got " << num(ratio));
                }
        CHECK_MESSAGE(bad == 0, cc.name << ": " << bad << " of 294 raster positions give a weight other than 1");
    }
}
