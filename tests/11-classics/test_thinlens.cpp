// Lesson 11, graded: the thin lens's pieces (Eq. 11.10-11.15 of lessons/11-classics/README.md),
// each against geometry and quadratures computed here in double from the camera's parameters
// alone (lens_support.h), on three cameras: square and looking down +z; wide, oblique, with a
// lens larger than the image's shift per pixel; tall, far from the origin, focused close.
//   lensPoint / pdfLens          a 64 x 64 grid of u fills the lens disk evenly (rings and sectors)
//   lensRay                      every lens point's ray through a raster position meets the plane
//                                of focus in the one point the pinhole's ray meets; radius -> 0
//                                gives the pinhole's rays
//   lensRasterOfDirection        inverts lensRay; a point off the plane of focus lands where its
//                                ray through the lens point crosses that plane
//   lensWe                       integrates to 1 over each pixel's directions from every lens point
//                                (times the lens's area); 0 outside the image and behind the lens
//   lensPdfDirection             integrates to 1 over the image; equals the density of lensRay's
//                                directions (their spread per raster area, by finite differences)
#include "lens_support.h"

using namespace lens11;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Lens points at the centre, half way out and on the rim (8 directions each).
std::vector<DVec3> probeLensPoints(const LensCase& c) {
    std::vector<DVec3> z = {DVec3(c.eye)};
    for (const double rho : {0.5, 0.999})
        for (int k = 0; k < 8; ++k) z.push_back(c.lensAt(rho, kPi * (0.125 + 0.25 * k)));
    return z;
}

// Integral over the focal-plane rectangle of raster [x0, x1] x [y0, y1], seen from lens point z, of
// g(direction, cos theta) d omega (theta: the angle to forward): a g x g midpoint rule on the plane, d omega = cos^3 / F^2 dA.
template <class G>
double integrateOverRaster(const LensCase& c, const DVec3& z, double x0, double y0, double x1, double y1, int n,
                           G&& g) {
    const double F = c.focus;
    const double cellArea = (F * 2.0 * c.tx() * (x1 - x0) / c.w) * (F * 2.0 * c.ty() * (y1 - y0) / c.h) / (n * n);
    double sum = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const DVec3 q = c.focal(x0 + (x1 - x0) * (i + 0.5) / n, y0 + (y1 - y0) * (j + 0.5) / n);
            const DVec3 w = glm::normalize(q - z);
            const double cosT = glm::dot(w, c.f());
            sum += g(Vec3(w), cosT) * cosT * cosT * cosT / (F * F) * cellArea;
        }
    return sum;
}

// What a wrong integral of W_e over a pixel suggests.
std::string hint(double I, double lensArea) {
    if (std::abs(I / lensArea - 1.0) < 0.02)
        return " (pi r^2 times too large: W_e without the lens's own 1 / (pi r^2)?)";
    if (I < 0.99 && I > 0.0)
        return " (cos^4 theta: one cosine for the lens's projected area, three for the solid angle; and inside the "
               "image is where the ray from z crosses the plane of focus, not where the pinhole would see it)";
    return " (W_e = 1 / (pi r^2 A cos^4 theta), A = imagePlaneArea())";
}

}  // namespace

TEST_CASE("thin lens: lensPoint fills the lens disk evenly, and pdfLens is its density (Eq. 11.10, 11.11) [2 pts]") {
    for (const LensCase& c : lensCases()) {
        CAPTURE(c.describe());
        const ps::ThinLens cam = c.camera();
        constexpr int n = 64;
        const double R = c.radius;
        const double scale = std::max(1.0, double(ps::maxAbsComponent(c.eye)));
        int bad = 0;
        std::vector<int> ring(4, 0), sector(8, 0);
        double farthest = 0.0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const Vec2 u((i + 0.5f) / n, (j + 0.5f) / n);
                const DVec3 d = lensPointD(cam, u) - DVec3(c.eye);
                const double along = glm::dot(d, c.f());
                const DVec3 inPlane = d - along * c.f();
                const double rho = glm::length(inPlane) / R;
                farthest = std::max(farthest, rho);
                if (std::abs(along) > 1e-5 * scale + 1e-5 * R || rho > 1.0 + 1e-4) {
                    if (bad++ == 0)
                        FAIL_CHECK("lensPoint(" << str(u) << ") = " << str(Vec3(DVec3(c.eye) + d))
                                                << ": expected a point of the lens, the disk of radius " << num(R)
                                                << " about the eye in the plane spanned by right and up; it lies "
                                                << num(rho * R) << " from the centre in that plane and " << num(along)
                                                << " off it (the unit disk's point scaled by the lens radius?)");
                    continue;
                }
                ++ring[std::min(3, int(rho * 4.0))];
                const double phi = std::atan2(glm::dot(inPlane, c.u()), glm::dot(inPlane, c.r()));
                ++sector[std::min(7, int((phi + kPi) / (2.0 * kPi) * 8.0))];
            }
        CHECK_MESSAGE(farthest > 0.97, "the lens points reach only "
                                           << num(farthest)
                                           << " of the lens radius: expected the whole disk "
                                              "(the unit disk's point scaled by the radius?)");
        // Uniform over the disk: the ring between rho = k/4 and (k+1)/4 holds (2k + 1) / 16 of it.
        for (int k = 0; k < 4; ++k) {
            const double got = double(ring[size_t(k)]) / (n * n), want = (2.0 * k + 1.0) / 16.0;
            CHECK_MESSAGE(std::abs(got - want) < 0.015, "the lens points between "
                                                            << k << "/4 and " << k + 1 << "/4 of the radius: expected "
                                                            << num(want) << " of them, got " << num(got)
                                                            << " (uniform on the disk: lesson "
                                                               "1's concentric map)");
        }
        for (int k = 0; k < 8; ++k) {
            const double got = double(sector[size_t(k)]) / (n * n);
            CHECK_MESSAGE(std::abs(got - 0.125) < 0.015, "the lens points in the sector " << k << " of 8 (angle about "
                                                                                          << "the centre): expected "
                                                                                          << "0.125 of them, got "
                                                                                          << num(got));
        }
        // Its density: 1 / area of the disk.
        const double pdf = cam.pdfLens();
        CHECK_MESSAGE(std::abs(pdf * kPi * R * R - 1.0) < 1e-5,
                      "pdfLens(): expected 1 / (pi r^2) = " << num(1.0 / (kPi * R * R)) << " per unit area (r = "
                                                            << num(R) << "), got " << num(pdf));
    }
}

TEST_CASE(
    "thin lens: every lens point's ray through a raster position meets the plane of focus where the pinhole's ray "
    "does (Eq. 11.12) [2 pts]") {
    for (const LensCase& c : lensCases()) {
        CAPTURE(c.describe());
        const ps::ThinLens cam = c.camera();
        const double F = c.focus, scale = std::max(double(F), double(ps::maxAbsComponent(c.eye)));
        int failures = 0;
        for (const Vec2& raster : {Vec2(0.5f, 0.5f), Vec2(c.w - 0.5f, c.h - 0.5f), Vec2(0.5f * c.w, 0.5f * c.h),
                                   Vec2(0.25f, c.h - 0.75f), Vec2(0.8f * c.w, 0.3f * c.h)}) {
            const DVec3 want = c.focal(raster.x, raster.y);
            // Where the pinhole's ray meets the sphere of radius F (focus measured along the ray).
            const DVec3 dp = glm::normalize(want - DVec3(c.eye));
            const DVec3 onSphere = DVec3(c.eye) + double(F) * dp;
            for (const DVec3& z : probeLensPoints(c)) {
                const ps::Ray ray = cam.lensRay(raster, Vec3(z));
                const DVec3 o(ray.o), d(ray.d);
                const double toPlane = (F - glm::dot(o - DVec3(c.eye), c.f())) / glm::dot(d, c.f());
                const DVec3 got = o + toPlane * d;
                const double err = glm::length(got - want), tol = 2e-5 * scale;
                const bool ok = glm::length(o - z) <= 1e-5 * scale && std::abs(glm::length(d) - 1.0) < 1e-5 &&
                                glm::dot(d, c.f()) > 0.0 && err <= tol;
                if (!ok && failures++ < 3) {
                    // The closest point of the ray to the sphere's point: does it go there instead?
                    const double along = glm::dot(onSphere - o, d);
                    const bool sphere = glm::length(o + along * d - onSphere) <= tol;
                    FAIL_CHECK("lensRay(" << str(raster) << ", z = " << str(Vec3(z)) << ") = origin " << str(ray.o)
                                          << ", direction " << str(ray.d)
                                          << "\n  expected: origin z, a unit direction in front of the lens, and the "
                                             "ray through the plane of focus (depth "
                                          << num(F) << " along forward) at " << str(Vec3(want))
                                          << "\n  got: it crosses that plane at " << str(Vec3(got)) << ", " << num(err)
                                          << " away"
                                          << (sphere ? "; it meets eye + F * (the pinhole's unit direction) instead: "
                                                       "the focal distance is measured along the forward axis "
                                                       "(depth), not along the ray"
                                                     : ""));
                }
            }
        }
        CHECK(failures == 0);
    }
}

TEST_CASE("thin lens: as the lens radius goes to 0, lensRay gives the pinhole's rays [1 pt]") {
    for (const LensCase& base : lensCases()) {
        LensCase c = base;
        c.radius = 1e-5f * c.focus;
        CAPTURE(c.describe());
        const ps::ThinLens cam = c.camera();
        for (const Vec2& raster : {Vec2(0.5f, 0.5f), Vec2(c.w - 0.5f, 0.5f), Vec2(0.5f * c.w, 0.5f * c.h)})
            for (const Vec2& u : {Vec2(0.1f, 0.9f), Vec2(0.5f, 0.5f), Vec2(0.97f, 0.03f)}) {
                const ps::Ray lens = cam.lensRay(raster, cam.lensPoint(u));
                const DVec3 want = glm::normalize(c.focal(raster.x, raster.y) - DVec3(c.eye));
                const double err = glm::length(DVec3(lens.d) - want);
                CHECK_MESSAGE(err < 1e-4, "radius " << num(c.radius) << ": lensRay(" << str(raster) << ", lensPoint("
                                                    << str(u) << ")) has direction " << str(lens.d)
                                                    << ", expected the pinhole's " << str(Vec3(want)) << " (to 1e-4), "
                                                    << "off by " << num(err));
                CHECK_MESSAGE(glm::length(DVec3(lens.o) - DVec3(c.eye)) <= 2e-5 * c.focus + 1e-6 * std::abs(c.eye.x),
                              "radius " << num(c.radius) << ": the ray starts at " << str(lens.o)
                                        << ", expected the lens point, within the radius of the eye " << str(c.eye));
            }
    }
}

TEST_CASE("thin lens: lensRasterOfDirection is where a ray from a lens point lands on the image (Eq. 11.13) [1 pt]") {
    for (const LensCase& c : lensCases()) {
        CAPTURE(c.describe());
        const ps::ThinLens cam = c.camera();
        int failures = 0;
        for (const Vec2& raster : {Vec2(0.5f, 0.5f), Vec2(c.w - 0.5f, c.h - 0.5f), Vec2(0.3f * c.w, 0.6f * c.h)})
            for (const DVec3& z : probeLensPoints(c))
                for (const double depth : {1.0, 0.4, 2.5}) {  // x focus: on the plane of focus, before, behind it
                    // The point at `depth` on the pinhole's ray through raster, seen from z: its ray crosses the
                    // plane of focus at q; the image there is q's raster position.
                    const DVec3 p = DVec3(c.eye) + (c.focal(raster.x, raster.y) - DVec3(c.eye)) * depth;
                    const DVec3 w = p - z;
                    const DVec3 q = z + w * (double(c.focus) / glm::dot(w, c.f()));
                    const Vec2 want = c.rasterOfFocal(q);
                    const bool inside =
                        want.x > 0.01f && want.x < c.w - 0.01f && want.y > 0.01f && want.y < c.h - 0.01f;
                    Vec2 got(-1.0f);
                    const bool hit = cam.lensRasterOfDirection(Vec3(z), Vec3(glm::normalize(w)), got);
                    const bool outside =
                        !(want.x > -0.01f && want.x < c.w + 0.01f && want.y > -0.01f && want.y < c.h + 0.01f);
                    bool ok = true;  // within 0.01 of an edge either answer is right
                    if (inside) ok = hit && glm::length(got - want) < 2e-3f;
                    if (outside) ok = !hit;
                    if (!ok && failures++ < 3)
                        FAIL_CHECK("lensRasterOfDirection(z = "
                                   << str(Vec3(z)) << ", direction towards " << str(Vec3(p)) << "): expected "
                                   << (inside ? "raster " + str(want)
                                              : std::string("false (outside the image: ") + str(want) + ")")
                                   << ", got " << (hit ? str(got) : std::string("false"))
                                   << " (the point where the ray crosses the plane of "
                                      "focus, seen from the lens centre)");
                }
        // Behind the lens: false.
        Vec2 r;
        CHECK_MESSAGE(!cam.lensRasterOfDirection(Vec3(probeLensPoints(c)[3]), Vec3(-c.f()), r),
                      "lensRasterOfDirection of a direction behind the lens (-forward): expected false");
        CHECK(failures == 0);
    }
}

TEST_CASE(
    "thin lens: W_e integrates to 1 over the lens and each pixel's directions, and is 0 outside the image "
    "(Eq. 11.14) [2 pts]") {
    for (const LensCase& c : lensCases()) {
        CAPTURE(c.describe());
        const ps::ThinLens cam = c.camera();
        const double lensArea = kPi * double(c.radius) * c.radius, wh = double(c.w) * c.h;
        int failures = 0;
        // Corner, border and middle pixels: from a rim lens point a border pixel's directions lie
        // partly outside the image the pinhole would see.
        const std::vector<std::pair<int, int>> pixels = {
            {0, 0}, {c.w - 1, 0}, {0, c.h - 1}, {c.w - 1, c.h / 2}, {c.w / 2, c.h / 2}};
        for (const DVec3& z : probeLensPoints(c))
            for (const auto& [px, py] : pixels) {
                const double I =
                    lensArea * integrateOverRaster(c, z, px, py, px + 1, py + 1, 6, [&](const Vec3& w, double cosT) {
                        return wh * double(cam.lensWe(Vec3(z), w)) * cosT;
                    });
                if (!(std::abs(I - 1.0) < 2e-3) && failures++ < 4)
                    FAIL_CHECK("pixel (" << px << ", " << py << ") seen from lens point " << str(Vec3(z))
                                         << ": expected pi r^2 times the integral of width * height * W_e(z, w) "
                                            "cos(theta) over the pixel's directions to be 1, got "
                                         << num(I) << hint(I, lensArea));
            }
        // The whole image from the lens centre: 1 / (pi r^2).
        const DVec3 z0(c.eye);
        const double all = integrateOverRaster(c, z0, 0, 0, c.w, c.h, 48, [&](const Vec3& w, double cosT) {
            return double(cam.lensWe(Vec3(z0), w)) * cosT;
        });
        CHECK_MESSAGE(
            std::abs(all * lensArea - 1.0) < 2e-3,
            "the integral of W_e(z, w) cos(theta) over the whole image from the lens centre: expected 1 / (pi "
            "r^2) = "
                << num(1.0 / lensArea) << ", got " << num(all)
                << " (W_e = 1 / (pi r^2 A cos^4 theta): the lens's own 1 / (pi r^2)?)");
        // Outside the image (half a pixel beyond each edge, from rim points) and behind the lens: 0.
        for (const DVec3& z : probeLensPoints(c))
            for (const Vec2& out : {Vec2(-0.5f, 0.5f * c.h), Vec2(c.w + 0.5f, 0.5f * c.h), Vec2(0.5f * c.w, -0.5f),
                                    Vec2(0.5f * c.w, c.h + 0.5f)}) {
                const Vec3 w(glm::normalize(c.focal(out.x, out.y) - z));
                const float we = cam.lensWe(Vec3(z), w);
                if (we != 0.0f && failures++ < 8)
                    FAIL_CHECK("W_e(" << str(Vec3(z)) << ", " << str(w) << "), a direction whose ray lands at raster "
                                      << str(out) << " (outside the image): expected 0, got " << num(we)
                                      << " (inside or not is where the ray crosses the plane of focus: "
                                         "lensRasterOfDirection)");
            }
        CHECK_MESSAGE(cam.lensWe(Vec3(z0), Vec3(-c.f())) == 0.0f, "W_e of a direction behind the lens: expected 0");
        CHECK(failures == 0);
    }
}

TEST_CASE(
    "thin lens: lensPdfDirection is the density of lensRay's directions: it integrates to 1 over the image and "
    "matches their spread (Eq. 11.15) [2 pts]") {
    for (const LensCase& c : lensCases()) {
        CAPTURE(c.describe());
        const ps::ThinLens cam = c.camera();
        int failures = 0;
        for (const DVec3& z : probeLensPoints(c)) {
            const double all = integrateOverRaster(c, z, 0, 0, c.w, c.h, 32, [&](const Vec3& w, double) {
                return double(cam.lensPdfDirection(Vec3(z), w));
            });
            const double corner = integrateOverRaster(c, z, c.w - 1, c.h - 1, c.w, c.h, 6, [&](const Vec3& w, double) {
                return double(cam.lensPdfDirection(Vec3(z), w));
            });
            if (!(std::abs(all - 1.0) < 2e-3 && std::abs(corner * c.w * c.h - 1.0) < 2e-3) && failures++ < 3)
                FAIL_CHECK("from lens point " << str(Vec3(z)) << ": expected the density of directions to integrate to "
                                              << "1 over the image and to 1 / (width * height) over the corner pixel, "
                                                 "got "
                                              << num(all) << " and " << num(corner) << " x width * height"
                                              << " (1 / (A cos^3 theta) where the ray lands in the image)");
        }
        // Sample / pdf consistency: raster positions are uniform (density 1 / (w h) per unit raster
        // area); the directions lensRay makes of them spread over a solid angle per raster area
        // that finite differences measure. Their density is the ratio.
        // (Near the origin only: 300 m away float rounds the directions by more than a small step moves them.)
        const double delta = 0.02;
        if (ps::maxAbsComponent(c.eye) < 10.0f)
            for (const Vec2& raster : {Vec2(0.3f, 0.4f), Vec2(0.5f * c.w, 0.5f * c.h), Vec2(c.w - 0.6f, c.h - 0.3f)})
                for (const DVec3& z : {DVec3(c.eye), probeLensPoints(c)[12]}) {
                    const DVec3 d0(cam.lensRay(raster, Vec3(z)).d);
                    const DVec3 d1(cam.lensRay(raster + Vec2(float(delta), 0.0f), Vec3(z)).d);
                    const DVec3 d2(cam.lensRay(raster + Vec2(0.0f, float(delta)), Vec3(z)).d);
                    const double solidAngle = glm::length(glm::cross(d1 - d0, d2 - d0)) / (delta * delta);
                    const double want = 1.0 / (double(c.w) * c.h * solidAngle);
                    const double got = cam.lensPdfDirection(Vec3(z), Vec3(d0));
                    if (!(std::abs(got / want - 1.0) < 1e-2) && failures++ < 6)
                        FAIL_CHECK("raster " << str(raster) << ", lens point " << str(Vec3(z))
                                             << ": lensRay's directions cover " << num(solidAngle)
                                             << " sr per unit raster area, so their density is " << num(want)
                                             << "; lensPdfDirection says " << num(got));
                }
        CHECK(failures == 0);
    }
}
