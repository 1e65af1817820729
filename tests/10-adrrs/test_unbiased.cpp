// Lesson 10, graded: survival and splitting change how much work goes where, never the expected
// image: pt-adrrs on the Cornell box (scenes/cornell-box.scene at 32 x 32, maximum depth 8) must
// converge to lesson 3's stored path-traced reference (tests/03-path-tracing/data: 262144 spp of pt
// and its variance of the mean) with the pre-pass's cache, and with a deliberately bad one: every
// entry random, log-uniform in [0.1, 10] per channel and unrelated to the scene (one in 8 black),
// so the decisions are wrong by up to a factor 100 either way and the image must still be right.
// (A cache that is wronger is still unbiased, but its weights multiply into a heavy tail that the
// per-pixel variance estimate of 512 spp misses: log-uniform in [0.01, 100], the z-test rejected 1
// run of 13; in [0.001, 1000], every run. README, pitfalls.) Per-pixel z-test at level alpha() (lesson10.h): each of the
// 3072 pixel channels at the Sidak level of alpha() over the channels, at least 99.75 % must pass;
// 20 shifted seeds (PATHSPACE_TEST_SEED 0-19) all pass.
#include "lesson10.h"
#include "render.h"

using namespace lesson10;

namespace {

void checkCornell(const char* what, ps::ADRRSPathTracer& adrrs, int spp, uint64_t seed) {
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 32, 32);
    const ps::Image ref = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32-variance.pfm"));
    ps::RenderOptions opt;
    opt.spp = spp;
    opt.seed = ps::testseed::seed(seed);
    opt.threads = 1;
    const ps::RenderResult r = ps::render(scene, adrrs, opt);
    const ps::PathCounts& c = adrrs.counts();
    CHECK_MESSAGE(r.stats.bad() == 0, "pt-adrrs " << what
                                                  << " on the Cornell box: expected 0 NaN and 0 Inf samples, got "
                                                  << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
    CHECK_MESSAGE((c.roulette > 0 && c.splits > 0),
                  "pt-adrrs " << what
                              << " on the Cornell box: expected the rule to ask for roulette (q < 1) and for "
                                 "splitting (q > 1) somewhere, got "
                              << c.decisions << " decisions, " << c.roulette << " with q < 1, " << c.splits
                              << " with q > 1");
    // The whole image's mean (all pixels, r + g + b) against the reference's, at level alpha(): the
    // per-pixel test below judges each pixel at its own noise (median relative standard error 5.4 %
    // at 512 spp, and Sidak over 3072 channels), so a bias that darkens every pixel by a few % passes
    // it; the mean of 1024 independent pixels has a standard error of 0.43 % (measured with the
    // reference solution, both caches; the bound on the channels' covariance below makes it
    // conservative), so a bias of the whole image above about 4.4 standard errors, ~2 %, fails
    // here. (Measured: every continuation 3 % too light darkens the image by 1.1-1.4 %, z = -2.6
    // and -3.3: below that power.)
    {
        const ps::Image img = r.film.mean(), var = r.film.varianceOfMean();
        double diff = 0.0, v = 0.0, sum = 0.0;
        for (size_t p = 0; p < img.pixels.size(); ++p) {
            diff += ps::testrender::sum(img.pixels[p]) - ps::testrender::sum(ref.pixels[p]);
            sum += ps::testrender::sum(ref.pixels[p]);
            // Pixels are independent; their channels are not: Var(r + g + b) <= 3 (Var r + Var g + Var b).
            v += 3.0 * (ps::testrender::sum(var.pixels[p]) + ps::testrender::sum(refVar.pixels[p]));
        }
        const double zMean = diff / std::sqrt(v), p = ps::stats::normalTwoSided(std::abs(zMean));
        MESSAGE("pt-adrrs " << what << ": image mean / reference " << num(1.0 + diff / sum) << ", standard error "
                            << num(std::sqrt(v) / sum) << ", z = " << num(zMean));
        CHECK_MESSAGE(p >= alpha(), "pt-adrrs " << what << " on the Cornell box (" << spp
                                                << " spp): expected the image's mean (all pixels, r + g + b) to "
                                                   "equal the reference's within its noise, got a ratio of "
                                                << num(1.0 + diff / sum) << " (z = " << num(zMean) << ", p = " << p
                                                << " < " << alpha() << "): a bias in every pixel");
    }
    const ps::stats::ZTestResult z =
        ps::stats::zTestImages(r.film.mean(), r.film.varianceOfMean(), ref, refVar, alpha());
    CHECK_MESSAGE(z.passed, "pt-adrrs " << what << " on the Cornell box (32 x 32, maxdepth 8, " << spp << " spp, seed "
                                        << seed
                                        << "): expected lesson 3's pt reference within its noise (a = yours, b = the "
                                           "reference), got\n  "
                                        << z.report << "\n  (" << c.decisions << " decisions: " << c.roulette
                                        << " roulette, " << c.splits
                                        << " splits; a survivor or a split path not weighted "
                                           "beta / q, or n not drawn with E[n] = q, biases the image)");
}

}  // namespace

TEST_CASE("pt-adrrs: converges to lesson 3's Cornell box reference (z-test) [2 pts]") {
    ps::ADRRSPathTracer adrrs;
    checkCornell("with the pre-pass's cache", adrrs, 512, 1021);
}

TEST_CASE("pt-adrrs: converges to the same reference with a random cache (z-test) [2 pts]") {
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 32, 32);
    ps::AdjointCache bad(scene.bounds, ps::kCacheResolution);
    ps::Rng rng(ps::testseed::seed(1022), 7);
    for (int e = 0; e < bad.entries(); ++e) {
        // log-uniform in [0.1, 10] per channel, one entry in 8 black (not reliable: lesson 3's roulette)
        const auto r = [&] { return std::pow(10.0f, 2.0f * rng.uniform() - 1.0f); };
        const Color c{r(), r(), r()};
        bad.set(e, rng.uniform() < 0.125f ? Color(0.0f) : c);
    }
    ps::ADRRSPathTracer adrrs;
    adrrs.useCache(bad);
    checkCornell("with a random cache", adrrs, 512, 1023);
}
