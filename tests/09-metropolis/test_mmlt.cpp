// Lesson 9, graded: the integrator mmlt (Eq. 9.12-9.16) on the Cornell box: each path length's
// b_k against lesson 7's per-length references, the image against lesson 3's reference (block
// t-tests of independent chains), the image's brightness against the b_k, and the same image for
// any number of threads.
#include "cornell_blocks.h"
#include "09-metropolis/mmlt.h"

using namespace lesson09;
using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;

namespace {

struct MMLTRender {
    ps::Image mean;
    ps::SampleStats stats;
    double b = 0.0;
    std::vector<ps::PathLength> lengths;
};

MMLTRender renderMMLT(const ps::Scene& scene, const ps::MMLTSettings& settings, int spp, uint64_t seed,
                      int threads = 1) {
    ps::MMLT mmlt(settings);
    const Rendered r = renderWith(mmlt, scene, spp, seed, threads);
    return {r.mean, r.stats, mmlt.b(), mmlt.lengths()};
}

// Mean luminance of a stored reference and its standard error: the per-pixel variances of the
// mean (independent pixels), luminance's channels bounded as if fully correlated.
struct Measured {
    double mean = 0.0, stdError = 0.0;
};
Measured referenceLuminance(const std::string& name) {
    const ps::Image img = ps::readPFM(sourcePath("tests/07-bidirectional/data/" + name + ".pfm"));
    const ps::Image var = ps::readPFM(sourcePath("tests/07-bidirectional/data/" + name + "-variance.pfm"));
    const double n = double(img.pixels.size());
    Measured m;
    double v = 0.0;
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        m.mean += double(ps::luminance(img.pixels[i])) / n;
        const ps::Color& s = var.pixels[i];
        const double sd = 0.2126 * std::sqrt(s.r) + 0.7152 * std::sqrt(s.g) + 0.0722 * std::sqrt(s.b);
        v += sd * sd / (n * n);
    }
    m.stdError = std::sqrt(v);
    return m;
}

}  // namespace

TEST_CASE("MMLT: each path length's b_k is the light of that length in the reference (z-tests, Eq. 9.15) [1 pt]") {
    // The Cornell box at 16 x 16 with maximum depth 2 (path lengths 1, 2, 3), the bootstrap only
    // (one iteration, 48 seed samples per pixel: 4096 per length; standard errors 0.1 %, 1.4 %, 1.8 %). Lesson 7's references hold pt at maximum depths 0, 1, 2 (262144 spp):
    // length k's light is depth k - 1 minus depth k - 2. Each b_k is a mean of independent seed
    // samples: z = (b_k - reference) / sqrt(its standard error^2 + the reference's^2), each of the
    // three at the Sidak share of alpha(). Power: b_k's standard error at most 3 % of the reference.
    ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 16, 16);
    scene.settings.maxDepth = 2;
    ps::MMLTSettings settings;
    settings.bootstrapPerPixel = 48;
    const MMLTRender r = renderMMLT(scene, settings, 1, ps::testseed::seed(1301));
    REQUIRE_MESSAGE(r.lengths.size() == 3,
                    "mmlt with maximum depth 2 should have path lengths 1 .. 3, got " << r.lengths.size());
    const Measured depth[3] = {referenceLuminance("cornell-box-16-depth0"), referenceLuminance("cornell-box-16-depth1"),
                               referenceLuminance("cornell-box-16-depth2")};
    const double a = ps::stats::sidak(alpha(), 3);
    const double zCrit = [a] {  // two-sided critical value of the standard normal at level a
        double lo = 0.0, hi = 10.0;
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (lo + hi);
            (ps::stats::normalTwoSided(mid) > a ? lo : hi) = mid;
        }
        return hi;
    }();
    for (int k = 1; k <= 3; ++k) {
        const ps::PathLength& l = r.lengths[size_t(k - 1)];
        const double want = depth[k - 1].mean - (k >= 2 ? depth[k - 2].mean : 0.0);
        const double seRef = std::sqrt(depth[k - 1].stdError * depth[k - 1].stdError +
                                       (k >= 2 ? depth[k - 2].stdError * depth[k - 2].stdError : 0.0));
        const double se = std::sqrt(l.bStdError * l.bStdError + seRef * seRef);
        const double z = (l.b - want) / se;
        const double ratio = l.b / want;
        std::string why;
        if (!(l.b > 0.0)) why = "no light found at this length";
        else if (std::abs(ratio * (k + 1) - 1.0) < 0.1)
            why =
                "b_k is about p_k(s) = 1 / (k + 1) of it: the target is missing the division by the probability of "
                "choosing the technique (Eq. 9.12)";
        else if (ratio > 1.5)
            why =
                "b_k is too large: every technique counting the whole path (the MIS weight left out of the target), "
                "or t = 1 without the factor 1 / (w h)?";
        else why = "the target of Eq. 9.12, or the mean of Eq. 9.15";
        CHECK_MESSAGE(std::abs(z) <= zCrit,
                      "path length k = " << k << ": expected b_k = " << num(want) << " (the reference's mean luminance "
                                         << "at length k), got " << num(l.b) << " +- " << num(l.bStdError) << " (ratio "
                                         << num(ratio) << ", z = " << num(z) << ", |z| <= " << num(zCrit)
                                         << " at alpha " << num(a) << " to pass): " << why);
        CHECK_MESSAGE(l.bStdError <= 0.03 * want,
                      "path length k = " << k << ": b_k's standard error " << num(l.bStdError) << " exceeds 3 % of "
                                         << num(want) << " (" << l.seeds << " seed samples)");
    }
}

TEST_CASE(
    "MMLT: multiplexed MLT equals the path-traced reference on the Cornell box (block t-tests of independent "
    "chains) [2 pts]") {
    ps::MMLTSettings settings;
    settings.chains = 16;
    settings.bootstrapPerPixel = 32;
    checkCornellBlocks(
        "mmlt",
        [&](const ps::Scene& scene, uint64_t seed) {
            ps::MMLT mmlt(settings);
            return renderWith(mmlt, scene, 64, seed);
        },
        64, 1311, 0.05,
        "all too bright or dark: the b_k (the target's 1 / p_k(s), its MIS weight); some: the technique mutation's "
        "transition probabilities, the weights 1 - a and a, the acceptance");
}

TEST_CASE("MMLT: the image's mean luminance is the sum of the b_k (Eq. 9.16) [1 pt]") {
    // Each step of a length-k chain splats luminance b_k pixels / M_k in all (weights 1 - a and
    // a, each colour divided by its own luminance): the image's mean luminance is the sum of the
    // b_k, up to float rounding (1e-4). This identity holds for any b_k; each b_k itself is judged
    // against an oracle of its own (lesson 7's per-length references) by the b_k test above.
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 16, 16);
    ps::MMLTSettings s;
    s.chains = 12;
    const MMLTRender r = renderMMLT(scene, s, 4, ps::testseed::seed(1321));
    const double m = meanLuminance(r.mean);
    REQUIRE_MESSAGE(r.b > 0.0, "the sum of the b_k is " << r.b << ": the bootstrap found no light in the Cornell box");
    CHECK_MESSAGE(std::abs(m - r.b) <= 1e-4 * r.b,
                  "mmlt on the Cornell box (16 x 16, 4 spp): expected the image's mean luminance to be the sum of "
                  "the b_k = "
                      << r.b << ", got " << m << " (ratio " << m / r.b
                      << "): splats not divided by I, weights 1 - a and a not summing to 1, or a splat lost?");
}

TEST_CASE("MMLT: the same seed gives the same image for 1 and 2 threads [1 pt]") {
    // 48 x 32 pixels, 256 chains: 4 tasks of 64 chains, so two threads share the work.
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 48, 32);
    ps::MMLTSettings s;
    s.chains = 256;
    const MMLTRender one = renderMMLT(scene, s, 2, ps::testseed::seed(1331), 1);
    const MMLTRender two = renderMMLT(scene, s, 2, ps::testseed::seed(1331), 2);
    REQUIRE_MESSAGE(meanLuminance(one.mean) > 0.0, "mmlt renders the Cornell box black");
    int differ = 0;
    for (size_t i = 0; i < one.mean.pixels.size(); ++i) {
        const ps::Color &p = one.mean.pixels[i], &q = two.mean.pixels[i];
        differ += p.r != q.r || p.g != q.g || p.b != q.b;
    }
    CHECK_MESSAGE(differ == 0, "mmlt, seed 1331, 1 and 2 threads: " << differ << " of " << one.mean.pixels.size()
                                                                    << " pixels differ (the chains' state or splats "
                                                                       "depend on which thread ran them)");
}
