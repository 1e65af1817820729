// Lesson 2, graded: every estimator converges to the same image. Each renders the moderate
// plates scene (data/plates-moderate.scene, 32 x 32) and is compared with the stored reference
// (data/plates-moderate.pfm and its variance of the mean, 262144 spp of direct-power; README
// section 4 has the command) by a per-pixel z-test at level alpha() (lesson02.h): each of the
// 3072 pixel channels at the Sidak level of alpha() over the channels, and at least 99.75 % of
// them must pass.
#include "lesson02.h"
#include "seed.h"

using namespace lesson02;

namespace {

constexpr int kSpp = 8192;  // a few thousand samples: every estimator's pixel means are near normal here

void checkConverges(const std::string& algo, uint64_t seed) {
    const ps::Scene scene = ps::loadScene(sourcePath("tests/02-direct-mis/data/plates-moderate.scene"));
    const ps::Image ref = readData("plates-moderate.pfm"), refVar = readData("plates-moderate-variance.pfm");
    const Render r = render(scene, algo, kSpp, ps::testseed::seed(seed));
    LESSON02_CHECK_FINITE(r);
    const ps::stats::ZTestResult z = ps::stats::zTestImages(r.mean, r.variance, ref, refVar, alpha());
    CHECK_MESSAGE(z.passed,
                  algo << " on the moderate plates (32 x 32, " << kSpp << " spp, seed " << seed
                       << "): expected the reference image within its noise (a = yours, b = the reference), got\n  "
                       << z.report);
}

}  // namespace

TEST_CASE("direct: light sampling converges to the reference image (z-test) [1 pt]") {
    checkConverges("direct-light", 31);
}

TEST_CASE("direct: BSDF sampling converges to the reference image (z-test) [1 pt]") {
    checkConverges("direct-bsdf", 32);
}

TEST_CASE("direct: multi-sample MIS converges to the reference image with each heuristic (z-test) [2 pts]") {
    checkConverges("direct-balance", 33);
    checkConverges("direct-power", 34);
    checkConverges("direct-max", 35);
}

TEST_CASE("direct: one-sample MIS converges to the reference image (z-test) [1 pt]") {
    checkConverges("direct-onesample", 36);
}
