#include <functional>
// Lesson 5, graded: light tracing and path tracing estimate the same measurements (lesson 4,
// Eq. 4.10, 4.11), so on the Cornell box (scenes/cornell-box.scene at 32 x 32, maxdepth 8: only
// diffuse surfaces and an area light, so every path can be sampled both ways) the light tracer
// must converge to lesson 3's stored path-traced reference (tests/03-path-tracing/data/
// cornell-box-32.pfm and its variance: 262144 spp of pt). Per-pixel z-tests at level alpha()
// (lesson05.h): each pixel channel at the Sidak level of alpha() over the channels, at least
// 99.75 % must pass.
#include "lesson05.h"
#include "seed.h"

using namespace lesson05;

namespace {

constexpr int kIterations = 2000;  // of 1024 light paths each
constexpr uint64_t kSeed = 5101;

const Render& cornellLT() {
    static const Render r =
        render(loadSceneAt("scenes/cornell-box.scene", 32, 32), "lt", kIterations, ps::testseed::seed(kSeed));
    return r;
}
ps::Image reference() { return ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm")); }
ps::Image referenceVariance() {
    return ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32-variance.pfm"));
}

}  // namespace

TEST_CASE("light tracing: the Cornell box equals the path-traced reference (z-test) [3 pts]") {
    const Render& r = cornellLT();
    CHECK_MESSAGE(r.stats.bad() == 0, "lt on the Cornell box: expected 0 NaN and 0 Inf samples, got "
                                          << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
    const ps::stats::ZTestResult z =
        ps::stats::zTestImages(r.mean, r.variance, reference(), referenceVariance(), alpha());
    CHECK_MESSAGE(z.passed, "lt on the Cornell box (32 x 32, maxdepth 8, "
                                << kIterations << " x 1024 light paths, seed " << kSeed
                                << "): expected the path-traced reference within its noise "
                                   "(a = yours, b = the reference), got\n  "
                                << z.report);
}

TEST_CASE(
    "light tracing: no dark or bright border: the Cornell box's border pixels equal the reference (z-test) [1 pt]") {
    // The 124 pixels of the outermost ring alone: a splat rounded to the wrong pixel, or dropped
    // at the right or bottom edge, shows here first. The ring's mean is also compared.
    const Render& r = cornellLT();
    const ps::Image ref = reference(), refVar = referenceVariance();
    std::vector<bool> ring(ref.pixels.size(), false);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) ring[size_t(y) * 32 + x] = x == 0 || y == 0 || x == 31 || y == 31;
    const ps::stats::ZTestResult z = ps::stats::zTestImages(select(r.mean, ring), select(r.variance, ring),
                                                            select(ref, ring), select(refVar, ring), alpha());
    CHECK_MESSAGE(z.passed,
                  "lt on the Cornell box, the 124 border pixels: expected the path-traced reference within its noise "
                  "(x is the index along the ring: a = yours, b = the reference), got\n  "
                      << z.report);
    for (const auto& edge : std::vector<std::pair<std::string, std::function<bool(int, int)>>>{
             {"left column", [](int x, int) { return x == 0; }},
             {"right column", [](int x, int) { return x == 31; }},
             {"top row", [](int, int y) { return y == 0; }},
             {"bottom row", [](int, int y) { return y == 31; }}}) {
        const std::string& name = edge.first;  // named, not bound: clang < 16 captures no binding in a lambda
        const std::function<bool(int, int)>& inEdge = edge.second;
        double a = 0.0, b = 0.0, va = 0.0, vb = 0.0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                if (inEdge(x, y)) {
                    a += sum(r.mean.at(x, y));
                    b += sum(ref.at(x, y));
                    const Color s = r.variance.at(x, y), t = refVar.at(x, y);
                    va += std::pow(std::sqrt(s.r) + std::sqrt(s.g) + std::sqrt(s.b), 2.0);
                    vb += std::pow(std::sqrt(t.r) + std::sqrt(t.g) + std::sqrt(t.b), 2.0);
                }
        const double zEdge = std::abs(a - b) / std::sqrt(va + vb + 1e-12);
        CHECK_MESSAGE(ps::stats::normalTwoSided(zEdge) >= alpha(),
                      "lt on the Cornell box, "
                          << name << ": expected the sum of its pixels (R + G + B) to be the reference's " << num(b)
                          << " +- " << num(std::sqrt(vb)) << ", got " << num(a) << " +- " << num(std::sqrt(va))
                          << " (z = " << num(zEdge, 4) << ")");
    }
}
