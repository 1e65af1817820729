// Lesson 5, graded: light tracing and specular surfaces.
//  - A glass or mirror sphere seen directly through the pinhole is black under light tracing:
//    the last vertex before the camera would have to be specular, and a delta BSDF sends
//    nothing towards the camera unless the camera lies exactly on its one direction (README
//    section 1.6). Everywhere else the light tracer must equal the path tracer, caustics
//    included (scenes/cornell-spheres.scene at 32 x 32 against a stored path-traced reference).
//  - A lamp inside a glass globe (scenes/glass-lamp.scene): all its light leaves the glass, so a
//    particle's power must be kept through refraction (no (eta_i / eta_t)^2, Eq. 5.8); with the
//    radiance rule the image is 2.25 times too bright. Against a stored path-traced reference
//    (the path tracer applies the radiance rule, which is right for radiance). At 8 x 8 pixels:
//    the path tracer must find the lamp through the glass by chance, and needs 262144 samples
//    per pixel even for about 4 % noise there.
// References: tests/05-light-tracing/data/cornell-spheres-32.pfm, glass-lamp-8.pfm and their
// variances; the commands are in lessons/05-light-tracing/README.md section 4. z-tests at level
// alpha() (lesson05.h).
#include "lesson05.h"
#include "seed.h"

using namespace lesson05;

namespace {

// Per pixel of a render of scene: does the first hit along rays through the pixel have a delta
// material? all = every ray of a 6 x 6 grid over the closed pixel (corners included) hits the
// same specular sphere, any = at least one ray hits a specular surface. The silhouette of one
// sphere is convex, so a pixel whose four corners see it is covered by it entirely. (Two
// spheres' silhouettes together are not convex: a sliver of the wall can show between them.)
struct SpecularCoverage {
    std::vector<bool> all, any;
};
SpecularCoverage specularCoverage(const ps::Scene& scene) {
    const int w = scene.camera.width(), h = scene.camera.height();
    SpecularCoverage cov{std::vector<bool>(size_t(w) * h, true), std::vector<bool>(size_t(w) * h, false)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const size_t k = size_t(y) * w + x;
            uint32_t first = ps::kNoPrimitive;
            for (int j = 0; j <= 5; ++j)
                for (int i = 0; i <= 5; ++i) {
                    ps::Ray ray = scene.camera.generateRay(
                        Vec2(x + std::min(i / 5.0f, 0.99999f), y + std::min(j / 5.0f, 0.99999f)));
                    ps::SurfacePoint sp;
                    const bool specular = scene.intersect(ray, sp) && scene.materials[sp.material].isDelta();
                    if (i == 0 && j == 0) first = specular ? sp.prim : ps::kNoPrimitive;
                    cov.all[k] = cov.all[k] && specular && sp.prim == first;
                    cov.any[k] = cov.any[k] || specular;
                }
        }
    return cov;
}

}  // namespace

TEST_CASE(
    "light tracing: glass and mirror spheres seen directly are black, the rest equals the path tracer (z-test) [2 pts]") {
    const ps::Scene scene = loadSceneAt("scenes/cornell-spheres.scene", 32, 32);
    const ps::Image ref = ps::readPFM(sourcePath("tests/05-light-tracing/data/cornell-spheres-32.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/05-light-tracing/data/cornell-spheres-32-variance.pfm"));
    constexpr int kIterations = 1500;
    const Render r = render(scene, "lt", kIterations, ps::testseed::seed(5201));
    CHECK_MESSAGE(r.stats.bad() == 0, "lt on cornell-spheres: expected 0 NaN and 0 Inf samples, got "
                                          << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
    const SpecularCoverage cov = specularCoverage(scene);
    // The spheres' own pixels: exactly black under light tracing; in the path tracer's image they
    // show the room (black only where the mirror reflects the open front of the box).
    int covered = 0, lit = 0, refLit = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            const size_t k = size_t(y) * 32 + x;
            if (!cov.all[k]) continue;
            ++covered;
            if (!ps::isBlack(r.mean.pixels[k]) && ++lit <= 3)
                FAIL_CHECK("lt on cornell-spheres: pixel ("
                           << x << ", " << y
                           << ") sees only the glass or mirror sphere: expected "
                              "exactly 0 (no light path can end with a specular vertex before the "
                              "pinhole), got "
                           << str(r.mean.pixels[k]));
            if (sum(ref.pixels[k]) > 0.0) ++refLit;
        }
    REQUIRE_MESSAGE(covered >= 40,
                    "test setup: expected at least 40 pixels entirely covered by the spheres, found " << covered);
    CHECK_MESSAGE(lit == 0, "lt on cornell-spheres: " << lit << " of the " << covered
                                                      << " pixels that see only a specular sphere are not black");
    CHECK_MESSAGE(refLit >= covered * 9 / 10,
                  "test setup: the path-traced reference should be lit in most of those pixels, it is in "
                      << refLit << " of " << covered);
    // Everywhere else (pixels whose 3 x 3 neighbourhood holds no specular surface at all): the
    // light tracer equals the path tracer, the caustics under the glass sphere included.
    std::vector<bool> diffuse(cov.any.size(), false);
    int nDiffuse = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            bool clear = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < 32 && yy < 32 && cov.any[size_t(yy) * 32 + xx]) clear = false;
                }
            diffuse[size_t(y) * 32 + x] = clear;
            nDiffuse += clear;
        }
    const ps::stats::ZTestResult z = ps::stats::zTestImages(select(r.mean, diffuse), select(r.variance, diffuse),
                                                            select(ref, diffuse), select(refVar, diffuse), alpha());
    CHECK_MESSAGE(z.passed, "lt on cornell-spheres (32 x 32, maxdepth 8, "
                                << kIterations << " x 1024 light paths), the " << nDiffuse
                                << " pixels away from the spheres: expected the path-traced "
                                   "reference within its noise (x is the index among those "
                                   "pixels: a = yours, b = the reference), got\n  "
                                << z.report);
}

TEST_CASE(
    "light tracing: a lamp inside a glass globe: the power of particles leaving the glass is kept (Eq. 5.8, z-test) [2 pts]") {
    const ps::Scene scene = loadSceneAt("scenes/glass-lamp.scene", 8, 8);
    const ps::Image ref = ps::readPFM(sourcePath("tests/05-light-tracing/data/glass-lamp-8.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/05-light-tracing/data/glass-lamp-8-variance.pfm"));
    constexpr int kIterations = 4000;
    const Render r = render(scene, "lt", kIterations, ps::testseed::seed(5301));
    CHECK_MESSAGE(r.stats.bad() == 0, "lt on glass-lamp: expected 0 NaN and 0 Inf samples, got "
                                          << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
    const double ratio = total(r.mean) / total(ref);
    const ps::stats::ZTestResult z = ps::stats::zTestImages(r.mean, r.variance, ref, refVar, alpha());
    CHECK_MESSAGE(z.passed, "lt on glass-lamp (8 x 8, maxdepth 8, "
                                << kIterations
                                << " x 64 light paths): expected the path-traced "
                                   "reference within its noise, got an image "
                                << num(ratio, 4)
                                << " times as bright as the reference (2.25 = 1.5^2 would be the "
                                   "radiance rule applied to particles; a = yours, b = the "
                                   "reference)\n  "
                                << z.report);
}
