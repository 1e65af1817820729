// Lesson 7, graded: bidirectional path tracing estimates the same measurements as the path
// tracer (lesson 3), so on the Cornell family at 32 x 32 (maxdepth 8) `bpt` must converge to the
// stored path-traced references: the Cornell box (lesson 3's), the Cornell spheres (mirror and
// glass, lesson 5's), the point light and the background (this lesson's; commands in the
// README). Per-pixel z-tests at level alpha() (lesson07.h), at least 99.75 % of the pixel
// channels must pass; every render has no NaN or Inf sample.
#include "lesson07.h"

using namespace lesson07;

namespace {

struct Case {
    std::string scene, reference;
    int iterations;
};

void checkAgainstReference(const Case& c, const std::string& algo, uint64_t seed) {
    const ps::Scene scene = loadSceneAt("scenes/" + c.scene + ".scene", 32, 32);
    const Render r = render(scene, algo, c.iterations, seed);
    CHECK_MESSAGE(r.stats.bad() == 0, algo << " on " << c.scene << ": expected 0 NaN and 0 Inf samples, got " << r.stats.nan
                                           << " NaN and " << r.stats.inf << " Inf");
    const ps::Image ref = ps::readPFM(sourcePath(c.reference + ".pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath(c.reference + "-variance.pfm"));
    const ps::stats::ZTestResult z = ps::stats::zTestImages(r.mean, r.variance, ref, refVar, alpha());
    CHECK_MESSAGE(total(r.mean) > 0.5 * total(ref), algo << " on " << c.scene << ": expected an image about as bright as the "
                                                         << "reference (sum " << num(total(ref)) << "), got " << num(total(r.mean)));
    CHECK_MESSAGE(z.passed, algo << " on " << c.scene << " (32 x 32, maxdepth 8, " << c.iterations << " spp, seed " << seed
                                 << "): expected the path-traced reference within its noise (a = yours, b = the reference), got\n  "
                                 << z.report);
}

}  // namespace

TEST_CASE("bpt equals the path-traced reference on the Cornell box, with the power and the balance heuristic (z-test) [3 pts]") {
    const Case c{"cornell-box", "tests/03-path-tracing/data/cornell-box-32", 256};
    checkAgainstReference(c, "bpt", 7101);
    checkAgainstReference(c, "bpt-balance", 7102);
}

TEST_CASE("bpt equals the path-traced reference on the Cornell spheres: mirror, glass and caustics (z-test) [2 pts]") {
    checkAgainstReference({"cornell-spheres", "tests/05-light-tracing/data/cornell-spheres-32", 384}, "bpt", 7103);
}

TEST_CASE("bpt equals the path-traced reference with a point light: no s = 0 technique (z-test) [2 pts]") {
    checkAgainstReference({"cornell-point-light", "tests/07-bidirectional/data/cornell-point-light-32", 256}, "bpt", 7104);
}

TEST_CASE("bpt equals the path-traced reference with a background light: vertices at infinity (z-test) [2 pts]") {
    checkAgainstReference({"cornell-background", "tests/07-bidirectional/data/cornell-background-32", 256}, "bpt", 7105);
}
