// Lesson 7, graded: every technique (s, t) alone is an unbiased estimate of the paths it can
// sample (Eq. 7.4). On the Cornell box (diffuse surfaces, an area light: every technique but
// t = 0 samples every path) the unweighted image of each technique of path length k (k edges,
// s + t = k + 1) must equal the path-traced reference restricted to that length: the
// difference of two stored pt renders with maxdepth k - 1 and k - 2 (16 x 16, 262144 spp each,
// commands in the README), compared on sums over 4 x 4 pixel blocks, every block channel must pass. Veach's pyramid rows 1-3: 9 z-tests at level alpha() (lesson07.h).
#include "lesson07.h"
#include "seed.h"

using namespace lesson07;

namespace {

constexpr int kMaxLength = 3;
constexpr int kSpp = 2048;
constexpr uint64_t kSeed = 7201;

const ps::TechniqueImages& techniques() {
    static const ps::TechniqueImages t = [] {
        ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 16, 16);
        return ps::renderTechniques(scene, kMaxLength, kSpp, ps::testseed::seed(kSeed), 1, ps::BptOptions{});
    }();
    return t;
}

// The reference of path length k and its variance of the mean.
std::pair<ps::Image, ps::Image> referenceOfLength(int k) {
    const auto depth = [](int d) {
        const std::string base = "tests/07-bidirectional/data/cornell-box-16-depth" + std::to_string(d);
        return std::make_pair(ps::readPFM(sourcePath(base + ".pfm")), ps::readPFM(sourcePath(base + "-variance.pfm")));
    };
    auto [img, var] = depth(k - 1);
    if (k >= 2) {
        const auto [lo, loVar] = depth(k - 2);
        for (size_t i = 0; i < img.pixels.size(); ++i) {
            img.pixels[i] -= lo.pixels[i];
            var.pixels[i] += loVar.pixels[i];
        }
    }
    return {img, var};
}

using ps::testrender::blocks;  // sums over b x b pixels: (0, 3) has a few hits per pixel

}  // namespace

TEST_CASE(
    "each technique alone is unbiased: Veach's pyramid rows 1-3 equal the path-traced reference of their path length (z-tests) [4 pts]") {
    const ps::TechniqueImages& t = techniques();
    REQUIRE(t.unweighted.size() == size_t(ps::techniqueCount(kMaxLength)));
    for (int k = 1; k <= kMaxLength; ++k) {
        const auto reference = referenceOfLength(k);
        const auto& ref = reference.first;  // named, not bound: clang < 16 captures no binding in a lambda
        const auto& refVar = reference.second;
        for (int s = 0; s <= k; ++s) {  // s = k + 1 is t = 0: the pinhole cannot be hit
            const int i = ps::techniqueIndex(s, k);
            const ps::stats::ZTestResult z =
                ps::stats::zTestImages(blocks(t.unweighted[size_t(i)], 4), blocks(t.unweightedSq[size_t(i)], 4),
                                       blocks(ref, 4), blocks(refVar, 4), alpha(), 1.0);
            CHECK_MESSAGE(total(t.unweighted[size_t(i)]) > 0.5 * total(ref),
                          "technique (s, t) = (" << s << ", " << k + 1 - s << "), path length " << k
                                                 << ": expected an image about as bright as the reference (sum "
                                                 << num(total(ref)) << "), got "
                                                 << num(total(t.unweighted[size_t(i)])));
            CHECK_MESSAGE(z.passed, "technique (s, t) = ("
                                        << s << ", " << k + 1 - s << ") alone, unweighted, path length " << k
                                        << " (Cornell box 16 x 16, " << kSpp << " spp, seed "
                                        << ps::testseed::seed(kSeed)
                                        << "): expected the reference of that length (a = yours, b = the "
                                           "reference; x, y index 4 x 4 blocks), got\n  "
                                        << z.report);
        }
    }
}

TEST_CASE("the weighted techniques of a path length add up to that length's reference, and t = 0 stays black [2 pts]") {
    // Exact bookkeeping, no new statistical test: the MIS-weighted images of a row must add up
    // to (almost) the same as the unweighted mean of the row's techniques, within 5 % over the
    // image (both are estimates of the same sum from the same samples).
    const ps::TechniqueImages& t = techniques();
    for (int k = 1; k <= kMaxLength; ++k) {
        double weighted = 0.0, unweightedMean = 0.0;
        for (int s = 0; s <= k; ++s) {
            weighted += total(t.weighted[size_t(ps::techniqueIndex(s, k))]);
            unweightedMean += total(t.unweighted[size_t(ps::techniqueIndex(s, k))]) / double(k + 1);
        }
        const double ref = total(referenceOfLength(k).first);
        CHECK_MESSAGE(std::abs(weighted - ref) <= 0.05 * ref,
                      "path length " << k << ": expected the MIS-weighted techniques to add up to the "
                                     << "reference's " << num(ref) << " (+- 5 %), got " << num(weighted)
                                     << " (the unweighted techniques' mean: " << num(unweightedMean) << ")");
        CHECK_MESSAGE(total(t.unweighted[size_t(ps::techniqueIndex(k + 1, k))]) == 0.0,
                      "technique (" << k + 1 << ", 0): expected black (the pinhole cannot be hit), got a sum of "
                                    << num(total(t.unweighted[size_t(ps::techniqueIndex(k + 1, k))])));
    }
}
