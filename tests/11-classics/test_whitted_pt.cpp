// Lesson 11, graded: Whitted's image is the path tracer's filtered to the paths Whitted carries.
// On scenes/cornell-whitted.scene (the Cornell spheres with a glossy Phong sphere, lit by two
// point lights; 24 x 24 pixels, maxdepth 6, ambient 0) whitted must match the stored reference
// tests/11-classics/data/cornell-whitted-24.pfm: `pt --paths 'L[DG]S*E|LS*E'` at 65536 spp, with
// its per-pixel variance of the mean (the README's figure block says how it was made). Whitted's
// own noise is only the pixel's jitter (antialiasing): 256 spp cost a fraction of a second. Per-pixel z-test at
// level alpha() (paths_support.h): each of the 1728 pixel channels at the Sidak level over the
// channels, at least 99.75 % must pass.
#include "paths_support.h"
#include "render.h"

using namespace lesson11paths;

TEST_CASE(
    "whitted: equals pt filtered to L[DG]S*E|LS*E on the Cornell box with point lights, a mirror, glass and "
    "Phong (z-test) [3 pts]") {
    const ps::Scene scene = loadSceneAt("scenes/cornell-whitted.scene", 24, 24);
    REQUIRE(scene.settings.maxDepth == 6);
    REQUIRE(ps::isBlack(ps::whittedAmbient(scene.settings)));
    const ps::Image ref = ps::readPFM(sourcePath("tests/11-classics/data/cornell-whitted-24.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/11-classics/data/cornell-whitted-24-variance.pfm"));
    const ps::testrender::Render w = ps::testrender::render(scene, "whitted", 256, ps::testseed::seed(1111));
    CHECK_MESSAGE(w.stats.bad() == 0, "whitted: expected no NaN or Inf sample, got " << w.stats.nan << " NaN and "
                                                                                     << w.stats.inf << " Inf");
    const double total = ps::testrender::total(w.mean), refTotal = ps::testrender::total(ref);
    const ps::stats::ZTestResult z = ps::stats::zTestImages(w.mean, w.variance, ref, refVar, alpha());
    CHECK_MESSAGE(z.passed, "whitted (256 spp) against pt filtered to L[DG]S*E|LS*E (a = yours, b = the reference): "
                                << z.report << "\n  image sums: whitted " << num(total) << ", reference "
                                << num(refTotal) << " (ratio " << num(total / refTotal)
                                << "; check 1/d^2 and the cosine of the point lights, the shadow rays, the glass's "
                                   "Fresnel weights and eta^2, the maximum depth)");
}
