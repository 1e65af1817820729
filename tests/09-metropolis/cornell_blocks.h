// Shared by lesson 9's image tests (pssmlt and mmlt): the Cornell box at 16 x 16 against lesson
// 3's stored path-traced reference, by t-tests on 4 x 4 block means of independent renders.
#pragma once
#include "lesson09.h"
#include <functional>
#include "image.h"
#include "lesson_files.h"
#include "render.h"

namespace lesson09 {

// One render of `spp` iterations with the integrator made by `make`: the mean image and counts.
struct Rendered {
    ps::Image mean;
    ps::SampleStats stats;
};
inline Rendered renderWith(ps::Integrator& integrator, const ps::Scene& scene, int spp, uint64_t seed,
                           int threads = 1) {
    ps::RenderOptions opt;
    opt.spp = spp;
    opt.seed = seed;
    opt.threads = threads;
    const ps::RenderResult r = ps::render(scene, integrator, opt);
    return {r.film.mean(), r.stats};
}

inline double meanLuminance(const ps::Image& img) {
    double s = 0.0;
    for (const ps::Color& c : img.pixels) s += double(ps::luminance(c));
    return s / double(img.pixels.size());
}

// The Cornell box at 16 x 16 against the stored 32 x 32 path-traced reference of lesson 3
// (tests/03-path-tracing/data/cornell-box-32.pfm: 262144 spp of pt, maximum depth 8; a pixel's
// value is the mean radiance over its area, so each 16 x 16 pixel is the mean of four reference
// pixels, and each 4 x 4 block of the 16 x 16 image the mean of 8 x 8 reference pixels; lesson 7's
// tests show that bpt, whose techniques mmlt samples, has the same expectation).
// kRenders independent renders (seeds apart: independent chains) give kRenders independent
// block means per block and channel; each of the 16 blocks x 3 channels is t-tested against the
// reference block at the Sidak share of alpha() over the 48 comparisons. Power: every block's
// standard error at most maxRelStdError of the larger of the block's reference value and the
// reference's mean over the image in that channel (MLT spends its effort where the image is
// bright: the dark corners are noisier, and an error there matters less; the blocks that see the
// light itself are 20 times brighter than the image's mean). The reference's own standard error
// (below 0.05 % per block) is left out. `render(scene, seed)` makes one render; `hint` says what
// to look at when blocks differ.
inline void checkCornellBlocks(const char* what, const std::function<Rendered(const ps::Scene&, uint64_t)>& render,
                               int spp, uint64_t seed, double maxRelStdError, const char* hint) {
    constexpr int kRes = 16, kBlock = 4, kBlocks = kRes / kBlock, kRenders = 32;
    const ps::Scene scene = ps::testfiles::loadSceneAt("scenes/cornell-box.scene", kRes, kRes);
    const ps::Image ref = ps::readPFM(ps::testfiles::sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm"));
    REQUIRE(ref.width == 2 * kRes);
    std::vector<ps::stats::Welford> w(kBlocks * kBlocks * 3);
    ps::stats::ImageWelford renders;  // for the images a failure writes
    uint64_t bad = 0;
    for (int k = 0; k < kRenders; ++k) {
        const Rendered r = render(scene, ps::testseed::seed(seed) + 7919 * uint64_t(k));
        bad += r.stats.bad();
        renders.add(r.mean);
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
    // On failure: the mean of the renders and its variance of the mean, and the reference at
    // 16 x 16 (each pixel the mean of four), for `pathspace compare`.
    auto images = [&]() {
        ps::Image ref16(kRes, kRes);
        for (int y = 0; y < kRes; ++y)
            for (int x = 0; x < kRes; ++x) {
                ps::Color c(0.0f);
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx) c += ref.pixels[size_t((2 * y + dy) * ref.width + 2 * x + dx)];
                ref16.pixels[size_t(y * kRes + x)] = 0.25f * c;
            }
        return ps::stats::writeFailedImages(renders.mean(), renders.varianceOfMean(), ref16, ps::Image());
    };
    CHECK_MESSAGE(failed == 0, what << " on the Cornell box (16 x 16, " << spp << " spp, " << kRenders
                                    << " independent renders): every 4 x 4 block should equal the path-traced "
                                       "reference, "
                                    << failed << " of 48 block channels differ (the first 4):" << report << "\n  ("
                                    << hint << ")\n  " << images());
}

}  // namespace lesson09
