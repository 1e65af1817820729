// Lesson 6, graded: path tracing and light tracing are two techniques of one integral (Eq. 6.2).
// On the gap box (tests/06-path-space/data/gap-box.scene, 16 x 16: a Cornell-like box of diffuse
// surfaces and an area light, so every technique s = 0 ... k can sample every path of length k;
// its walls do not touch, so G between surfaces is bounded and every technique has a finite
// variance, which the z-tests need; in the real Cornell box's corners (2,2) has none), the image of paths of length exactly k estimated by one
// technique alone (f / p_{s,t} with your f and p, renderTechnique) must equal the image of
// technique (1, k) (next-event estimation), for k = 2 and 3, z-tests over 2 x 2 pixel blocks at
// level alpha() (lesson06.h). And the sum over k = 1, 2, 3 of the (1, k) images must equal lesson 3's path
// tracer with maxdepth 2 (an independent estimator of the same sum). No NaN or Inf anywhere.
#include <map>
#include "lesson06.h"
#include "seed.h"

using namespace lesson06;
using ps::testrender::blocks;

namespace {

constexpr int kIterations = 16000;  // of 256 paths each
constexpr uint64_t kSeed = 6101;

const ps::Scene& gapBox() {
    static const ps::Scene s = [] { return ps::loadScene(sourcePath("tests/06-path-space/data/gap-box.scene")); }();
    return s;
}

const Render& technique(int k, int s) {
    static std::map<std::pair<int, int>, Render> cache;
    auto it = cache.find({k, s});
    if (it != cache.end()) return it->second;
    const ps::RenderResult r =
        ps::renderTechnique(gapBox(), k, s, kIterations, ps::testseed::seed(kSeed + uint64_t(10 * k + s)), 1);
    return cache[{k, s}] = Render{r.film.mean(), r.film.varianceOfMean(), r.stats};
}

void checkAgainstNEE(int k, int s) {
    const Render& a = technique(k, s);
    const Render& b = technique(k, 1);
    INFO("gap box 16 x 16, paths of length k = " << k << ", technique (s, t) = (" << s << ", " << k + 1 - s
                                                 << ") against (1, " << k << "), " << kIterations
                                                 << " x 256 paths each");
    CHECK_MESSAGE(a.stats.bad() == 0,
                  "expected 0 NaN and 0 Inf samples, got " << a.stats.nan << " NaN and " << a.stats.inf << " Inf");
    CHECK_MESSAGE(b.stats.bad() == 0, "technique (1, " << k << "): expected 0 NaN and 0 Inf samples, got "
                                                       << b.stats.nan << " NaN and " << b.stats.inf << " Inf");
    CHECK_MESSAGE(total(a.mean) > 0.0, "expected a lit image, got a black one (is f or p_{s,t} 0?)");
    CHECK_MESSAGE(total(b.mean) > 0.0,
                  "technique (1, " << k << "): expected a lit image, got a black one (is f or p_{s,t} 0?)");
    // Over 2 x 2 pixel blocks, every block channel at the Sidak share of alpha(): (0, k + 1) hits
    // the light by chance, and in a pixel that sees little of it (gap box pixel (2, 4), k = 2: a
    // mean of 0.0017) it may not hit it at all, a mean and a variance estimate of 0 that fail a
    // per-pixel z-test however right the pdfs are.
    const ps::stats::ZTestResult z = ps::stats::zTestImages(blocks(a.mean, 2), blocks(a.variance, 2), blocks(b.mean, 2),
                                                            blocks(b.variance, 2), alpha(), 1.0);
    CHECK_MESSAGE(z.passed, "expected the same image within the noise (a = ("
                                << s << ", " << k + 1 - s << "), b = (1, " << k
                                << "); x, y index 2 x 2 pixel blocks), got\n  " << z.report);
}

}  // namespace

TEST_CASE("path space: paths of length 2: techniques (0,3), (1,2), (2,1) give the same image (Eq. 6.2) [2 pts]") {
    checkAgainstNEE(2, 0);
    checkAgainstNEE(2, 2);
}

TEST_CASE(
    "path space: paths of length 3: techniques (0,4), (1,3), (2,2), (3,1) give the same image (Eq. 6.2) [3 pts]") {
    checkAgainstNEE(3, 0);
    checkAgainstNEE(3, 2);
    checkAgainstNEE(3, 3);
}

TEST_CASE(
    "path space: the sum over k = 1, 2, 3 of technique (1, k) equals lesson 3's path tracer at maxdepth 2 (Eq. 6.1) [2 pts]") {
    ps::Image sum(16, 16), var(16, 16);
    for (int k = 1; k <= 3; ++k) {
        const Render& r = technique(k, 1);
        CHECK_MESSAGE(r.stats.bad() == 0, "technique (1, " << k << "): expected 0 NaN and 0 Inf samples, got "
                                                           << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
        for (size_t i = 0; i < sum.pixels.size(); ++i) {
            sum.pixels[i] += r.mean.pixels[i];
            var.pixels[i] += r.variance.pixels[i];
        }
    }
    ps::Scene scene = gapBox();
    scene.settings.maxDepth = 2;
    std::unique_ptr<ps::Integrator> pt = ps::makeIntegrator("pt");
    ps::RenderOptions opt;
    opt.spp = 8000;
    opt.seed = ps::testseed::seed(kSeed);
    opt.threads = 1;
    const ps::RenderResult ref = ps::render(scene, *pt, opt);
    CHECK_MESSAGE(total(sum) > 0.0, "expected a lit image, got a black one (is f or p_{s,t} 0?)");
    const ps::stats::ZTestResult z =
        ps::stats::zTestImages(sum, var, ref.film.mean(), ref.film.varianceOfMean(), alpha());
    CHECK_MESSAGE(
        z.passed,
        "gap box 16 x 16: expected the sum over k = 1, 2, 3 of technique (1, k) (a) to equal pt with maxdepth 2 (b, "
        "8000 spp, seed "
            << opt.seed << ") within the noise, got\n  " << z.report);
}
