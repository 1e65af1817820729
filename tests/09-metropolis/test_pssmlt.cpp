// Lesson 9, graded: the integrator pssmlt (Eq. 9.7-9.11) on the Cornell box against lesson 3's
// stored path-traced reference, b against the image it makes, and the same image for any
// number of threads.
#include "cornell_blocks.h"
#include "09-metropolis/pssmlt.h"

using namespace lesson09;
using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;

namespace {

struct MLTRender {
    ps::Image mean;
    ps::SampleStats stats;
    double b = 0.0;
    int chains = 0;
};

MLTRender renderMLT(const ps::Scene& scene, const ps::MLTSettings& settings, int spp, uint64_t seed, int threads = 1) {
    ps::PSSMLT mlt(settings);
    const Rendered r = renderWith(mlt, scene, spp, seed, threads);
    return {r.mean, r.stats, mlt.b(), mlt.chains()};
}

void checkBlocks(const char* what, const ps::MLTSettings& settings, int spp, uint64_t seed, double maxRelStdError) {
    checkCornellBlocks(
        what,
        [&](const ps::Scene& scene, uint64_t s) {
            ps::PSSMLT mlt(settings);
            return renderWith(mlt, scene, spp, s);
        },
        spp, seed, maxRelStdError,
        "all too bright or dark: b or the splat factor b pixels / steps; some: the weights 1 - a and a, or the "
        "acceptance");
}

}  // namespace

TEST_CASE("PSSMLT: large steps only equal the path tracer on the Cornell box (block t-tests) [2 pts]") {
    // pLarge = 1: every proposal is a fresh path, accepted with min(1, I(y) / I(x)): an
    // independence sampler of I / b, splatted with expected values.
    ps::MLTSettings s;
    s.pLarge = 1.0f;
    s.chains = 16;
    s.bootstrapPerPixel = 64;
    checkBlocks("pssmlt with large steps only", s, 64, 971, 0.05);
}

TEST_CASE(
    "PSSMLT: the full sampler equals the path tracer on the Cornell box (block t-tests of independent chains) [2 pts]") {
    ps::MLTSettings s;
    s.chains = 16;
    s.bootstrapPerPixel = 64;
    checkBlocks("pssmlt (pLarge 0.3)", s, 64, 981, 0.05);
}

TEST_CASE("PSSMLT: the bootstrap's b is the mean luminance of the image (Eq. 9.10, 9.11) [1 pt]") {
    // Each step splats luminance b pixels / M in total (weights 1 - a and a, each colour divided
    // by its own luminance): the image's mean luminance is b, up to float rounding (1e-4).
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 16, 16);
    ps::MLTSettings s;
    s.chains = 8;
    const MLTRender r = renderMLT(scene, s, 4, ps::testseed::seed(991));
    const double m = meanLuminance(r.mean);
    CHECK_MESSAGE(r.b > 0.0, "b = " << r.b << ": the bootstrap found no light in the Cornell box");
    CHECK_MESSAGE(std::abs(m - r.b) <= 1e-4 * r.b,
                  "pssmlt on the Cornell box (16 x 16, 4 spp): expected the image's mean luminance to be b = "
                      << r.b << ", got " << m << " (ratio " << m / r.b
                      << "): splats not divided by I, weights not summing to 1, or a splat lost?");
    // The identity above holds for any b the bootstrap returns; an oracle of its own: b estimates
    // the mean luminance of the image (Eq. 9.7), which lesson 3's stored reference gives
    // (tests/03-path-tracing/data/cornell-box-32.pfm, the same camera: its mean over 32 x 32 pixels
    // is the 16 x 16 image's). 16 independent bootstraps of 64 seed paths per pixel, their mean
    // t-tested against it at alpha() (lesson09.h), standard error at most 2 % (measured 1.4 %: a
    // b off by a few % passes; the classic mistakes, a sum of channels for the luminance, a lost 1 / N,
    // a missing seed path, are far outside).
    const ps::Image ref = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm"));
    const double refMean = meanLuminance(ref);
    ps::stats::Welford bs;
    for (int j = 0; j < 16; ++j) {
        ps::MLTSettings one;
        one.chains = 1;
        one.bootstrapPerPixel = 64;
        bs.add(renderMLT(scene, one, 1, ps::testseed::seed(992) + uint64_t(j) * 7919u).b);
    }
    const ps::stats::TTestResult t = ps::stats::tTest(bs, refMean, alpha(), 0.02);
    CHECK_MESSAGE(t.passed,
                  "pssmlt's bootstrap on the Cornell box (16 x 16, 64 seed paths per pixel, 16 runs): "
                  "expected b = the mean luminance of lesson 3's reference, "
                      << num(refMean) << ", got " << num(bs.mean) << " on average (ratio " << num(bs.mean / refMean)
                      << ")\n  " << t.report << "\n  (b = the mean of I = luminance(f) over the seed paths, Eq. 9.10)");
}

TEST_CASE("PSSMLT: the same seed gives the same image for 1 and 2 threads [1 pt]") {
    // 48 x 32 pixels, 256 chains: 4 tasks of 64 chains, so two threads share the work.
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 48, 32);
    ps::MLTSettings s;
    s.chains = 256;
    const MLTRender one = renderMLT(scene, s, 3, ps::testseed::seed(995), 1);
    const MLTRender two = renderMLT(scene, s, 3, ps::testseed::seed(995), 2);
    REQUIRE_MESSAGE(meanLuminance(one.mean) > 0.0, "pssmlt renders the Cornell box black");
    int differ = 0;
    for (size_t i = 0; i < one.mean.pixels.size(); ++i) {
        const ps::Color &p = one.mean.pixels[i], &q = two.mean.pixels[i];
        differ += p.r != q.r || p.g != q.g || p.b != q.b;
    }
    CHECK_MESSAGE(differ == 0, "pssmlt, seed 995, 1 and 2 threads: " << differ << " of " << one.mean.pixels.size()
                                                                     << " pixels differ (the chains' state or splats "
                                                                        "depend on which thread ran them)");
}
