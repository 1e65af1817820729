// Lesson 9, graded: the integrator pssmlt (Eq. 9.7-9.11) on the Cornell box against lesson 3's
// stored path-traced reference, b against the image it makes, and the same image for any
// number of threads.
#include "lesson09.h"
#include <memory>
#include "09-metropolis/pssmlt.h"
#include "image.h"
#include "lesson_files.h"
#include "render.h"
#include "scene_loader.h"

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
    ps::RenderOptions opt;
    opt.spp = spp;
    opt.seed = seed;
    opt.threads = threads;
    const ps::RenderResult r = ps::render(scene, mlt, opt);
    return {r.film.mean(), r.stats, mlt.b(), mlt.chains()};
}

double meanLuminance(const ps::Image& img) {
    double s = 0.0;
    for (const ps::Color& c : img.pixels) s += double(ps::luminance(c));
    return s / double(img.pixels.size());
}

// The Cornell box at 16 x 16 against the stored 32 x 32 path-traced reference of lesson 3
// (tests/03-path-tracing/data/cornell-box-32.pfm: 262144 spp of pt, maximum depth 8; a pixel's
// value is the mean radiance over its area, so each 16 x 16 pixel is the mean of four reference
// pixels, and each 4 x 4 block of the 16 x 16 image the mean of 8 x 8 reference pixels).
// kRenders independent renders (seeds apart: independent chains) give kRenders independent
// block means per block and channel; each of the 16 blocks x 3 channels is t-tested against the
// reference block at the Sidak share of alpha() over the 48 comparisons. Power: every block's
// standard error at most maxRelStdError of the larger of the block's reference value and the
// reference's mean over the image in that channel (MLT spends its effort where the image is
// bright: the dark corners are noisier, and an error there matters less; the blocks that see the
// light itself are 20 times brighter than the image's mean). The reference's own standard error (below 0.05 % per block) is
// left out.
void checkBlocks(const char* what, const ps::MLTSettings& settings, int spp, uint64_t seed, double maxRelStdError) {
    constexpr int kRes = 16, kBlock = 4, kBlocks = kRes / kBlock, kRenders = 32;
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", kRes, kRes);
    const ps::Image ref = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm"));
    REQUIRE(ref.width == 2 * kRes);
    std::vector<ps::stats::Welford> w(kBlocks * kBlocks * 3);
    uint64_t bad = 0;
    for (int k = 0; k < kRenders; ++k) {
        const MLTRender r = renderMLT(scene, settings, spp, ps::testseed::seed(seed) + 7919 * uint64_t(k));
        bad += r.stats.bad();
        for (int by = 0; by < kBlocks; ++by)
            for (int bx = 0; bx < kBlocks; ++bx) {
                double s[3] = {0, 0, 0};
                for (int y = by * kBlock; y < (by + 1) * kBlock; ++y)
                    for (int x = bx * kBlock; x < (bx + 1) * kBlock; ++x) {
                        const ps::Color& c = r.mean.pixels[size_t(y * kRes + x)];
                        s[0] += c.r;
                        s[1] += c.g;
                        s[2] += c.b;
                    }
                for (int ch = 0; ch < 3; ++ch) w[size_t((by * kBlocks + bx) * 3 + ch)].add(s[ch] / (kBlock * kBlock));
            }
    }
    CHECK_MESSAGE(bad == 0, what << ": " << bad << " NaN/Inf samples");
    const double a = ps::stats::sidak(alpha(), kBlocks * kBlocks * 3);
    double refMean[3] = {0, 0, 0};
    for (const ps::Color& c : ref.pixels) {
        refMean[0] += c.r / double(ref.pixels.size());
        refMean[1] += c.g / double(ref.pixels.size());
        refMean[2] += c.b / double(ref.pixels.size());
    }
    int failed = 0;
    std::string report;
    for (int by = 0; by < kBlocks; ++by)
        for (int bx = 0; bx < kBlocks; ++bx) {
            double s[3] = {0, 0, 0};
            for (int y = 2 * by * kBlock; y < 2 * (by + 1) * kBlock; ++y)
                for (int x = 2 * bx * kBlock; x < 2 * (bx + 1) * kBlock; ++x) {
                    const ps::Color& c = ref.pixels[size_t(y * ref.width + x)];
                    s[0] += c.r;
                    s[1] += c.g;
                    s[2] += c.b;
                }
            for (int ch = 0; ch < 3; ++ch) {
                const double want = s[ch] / (4 * kBlock * kBlock);
                const ps::stats::TTestResult t = ps::stats::tTest(w[size_t((by * kBlocks + bx) * 3 + ch)], want, a,
                                                                  maxRelStdError * std::max(want, refMean[ch]) / want);
                if (!t.passed) {
                    ++failed;
                    if (failed <= 4)
                        report += "\n  block (" + std::to_string(bx) + ", " + std::to_string(by) + ") " + "RGB"[ch] +
                                  ": " + t.report;
                }
            }
        }
    CHECK_MESSAGE(failed == 0, what << " on the Cornell box (16 x 16, " << spp << " spp, " << kRenders
                                    << " independent renders): every 4 x 4 block should equal the path-traced "
                                       "reference, "
                                    << failed << " of 48 block channels differ (the first 4):" << report
                                    << "\n  (all too bright or dark: b or the splat factor b pixels / steps; some: "
                                       "the weights 1 - a and a, or the acceptance)");
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
