// Lesson 3, graded: the three path tracers solve the same equation, so on the Cornell box
// (scenes/cornell-box.scene at 32 x 32, maximum depth 8) each must converge to the stored
// reference (data/cornell-box-32.pfm and its variance of the mean: 262144 spp of pt; README
// section 4 has the command). Per-pixel z-test at level alpha() (lesson03.h): each of the 3072
// pixel channels at the Sidak level of alpha() over the channels, at least 99.75 % must pass.
#include "lesson03.h"
#include "seed.h"

using namespace lesson03;

namespace {

void checkCornell(const std::string& algo, int spp, uint64_t seed) {
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 32, 32);
    const ps::Image ref = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32-variance.pfm"));
    const Render r = render(scene, algo, spp, ps::testseed::seed(seed));
    CHECK_MESSAGE(r.stats.bad() == 0, algo << " on the Cornell box: expected 0 NaN and 0 Inf samples, got "
                                           << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
    const ps::stats::ZTestResult z = ps::stats::zTestImages(r.mean, r.variance, ref, refVar, alpha());
    CHECK_MESSAGE(z.passed,
                  algo << " on the Cornell box (32 x 32, maxdepth 8, " << spp << " spp, seed " << seed
                       << "): expected the reference image within its noise (a = yours, b = the reference), got\n  "
                       << z.report);
}

}  // namespace

TEST_CASE("path tracing: BSDF sampling only converges to the Cornell box reference (z-test) [1 pt]") {
    checkCornell("pt-bsdf", 16384, 501);
}

TEST_CASE("path tracing: next-event estimation converges to the Cornell box reference (z-test) [1 pt]") {
    checkCornell("pt-nee", 2048, 502);
}

TEST_CASE("path tracing: MIS converges to the Cornell box reference (z-test) [1 pt]") { checkCornell("pt", 2048, 503); }

TEST_CASE("path tracing: no NaN or Inf in any scene of scenes/ [1 pt]") {
    // Every scene the course ships (glass, mirrors, a point light, the background, tiny bright
    // lights, Phong exponent 10000) at 16 x 16 pixels, 16 spp, with all three path tracers: no
    // sample may be NaN or Inf, and the images of pt-nee and pt must not be black. (BSDF
    // sampling alone may well be black: no path ever hits a point light, and at 16 spp few
    // find the small light of cornell-small-light.)
    for (const std::string file :
         {"cornell-box", "cornell-small-light", "cornell-point-light", "cornell-background", "cornell-spheres",
          "cornell-glossy", "veach-plates", "furnace", "point-in-sphere", "mesh-example"}) {
        const ps::Scene scene = loadSceneAt("scenes/" + file + ".scene", 16, 16);
        for (const std::string algo : {"pt-bsdf", "pt-nee", "pt"}) {
            const Render r = render(scene, algo, 16, ps::testseed::seed(511));
            double total = 0.0;
            for (const Color& c : r.mean.pixels) total += sum(c);
            const bool lit = algo != "pt-bsdf";
            CHECK_MESSAGE((r.stats.bad() == 0 && (total > 0.0 || !lit)),
                          algo << " on scenes/" << file << ".scene (16 x 16, 16 spp): expected 0 NaN, 0 Inf"
                               << (lit ? " and a lit image" : "") << ", got " << r.stats.nan << " NaN, " << r.stats.inf
                               << " Inf, sum of all pixels " << total);
        }
    }
}
