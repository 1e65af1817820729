// Lesson 7, graded: bidirectional path tracing estimates the same measurements as the path
// tracer (lesson 3), so on the Cornell family at 32 x 32 (maxdepth 8) `bpt` must converge to the
// stored path-traced references: the Cornell box (lesson 3's), the Cornell spheres (mirror and
// glass, lesson 5's), the point light and the background (this lesson's; commands in the
// README). Per-pixel z-tests at level alpha() (lesson07.h), at least 99.75 % of the pixel
// channels must pass; every render has no NaN or Inf sample.
#include "lesson07.h"
#include "seed.h"

using namespace lesson07;

namespace {

struct Case {
    std::string scene, reference;
    int iterations;
};

void checkAgainstReference(const Case& c, const std::string& algo, uint64_t baseSeed) {
    const uint64_t seed = ps::testseed::seed(baseSeed);
    const ps::Scene scene = loadSceneAt("scenes/" + c.scene + ".scene", 32, 32);
    const Render r = render(scene, algo, c.iterations, seed);
    CHECK_MESSAGE(r.stats.bad() == 0, algo << " on " << c.scene << ": expected 0 NaN and 0 Inf samples, got "
                                           << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
    const ps::Image ref = ps::readPFM(sourcePath(c.reference + ".pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath(c.reference + "-variance.pfm"));
    const ps::stats::ZTestResult z = ps::stats::zTestImages(r.mean, r.variance, ref, refVar, alpha());
    CHECK_MESSAGE(total(r.mean) > 0.5 * total(ref),
                  algo << " on " << c.scene << ": expected an image about as bright as the "
                       << "reference (sum " << num(total(ref)) << "), got " << num(total(r.mean)));
    CHECK_MESSAGE(
        z.passed,
        algo << " on " << c.scene << " (32 x 32, maxdepth 8, " << c.iterations << " spp, seed " << seed
             << "): expected the path-traced reference within its noise (a = yours, b = the reference), got\n  "
             << z.report);
}

}  // namespace

TEST_CASE(
    "bpt equals the path-traced reference on the Cornell box, with the power and the balance heuristic (z-test) [3 pts]") {
    const Case c{"cornell-box", "tests/03-path-tracing/data/cornell-box-32", 256};
    checkAgainstReference(c, "bpt", 7101);
    checkAgainstReference(c, "bpt-balance", 7102);
}

namespace {
// Per pixel: does any ray of a 6 x 6 grid over the pixel first hit a specular surface?
std::vector<bool> seesSpecular(const ps::Scene& scene) {
    return ps::testrender::pixelsWhere(scene, false, [&](bool hit, const ps::SurfacePoint& sp) {
        return hit && scene.materials[size_t(sp.material)].isDelta();
    });
}
ps::Image select(const ps::Image& img, const std::vector<bool>& mask) {
    int n = 0;
    for (bool m : mask) n += m;
    ps::Image out(n, 1);
    int k = 0;
    for (size_t i = 0; i < img.pixels.size(); ++i)
        if (mask[i]) out.pixels[size_t(k++)] = img.pixels[i];
    return out;
}
}  // namespace

TEST_CASE("bpt equals the path-traced reference on the Cornell spheres: mirror, glass and caustics (z-test) [2 pts]") {
    // Away from the spheres (no specular surface in a pixel's 3 x 3 neighbourhood; the caustic
    // under the glass sphere included): a per-pixel z-test. The spheres' own pixels show paths
    // like L S S D S S E that only s = 0 samples (as the path tracer does): rare, large samples,
    // for which a per-pixel variance estimate from a few hundred samples is unreliable; there
    // the sum over all sphere pixels must be within 10 % of the reference's.
    const ps::Scene scene = loadSceneAt("scenes/cornell-spheres.scene", 32, 32);
    constexpr int kIterations = 512;
    const uint64_t kSeedSpheres = ps::testseed::seed(7103);
    const Render r = render(scene, "bpt", kIterations, kSeedSpheres);
    CHECK_MESSAGE(r.stats.bad() == 0, "bpt on cornell-spheres: expected 0 NaN and 0 Inf samples, got "
                                          << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
    const ps::Image ref = ps::readPFM(sourcePath("tests/05-light-tracing/data/cornell-spheres-32.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/05-light-tracing/data/cornell-spheres-32-variance.pfm"));
    const std::vector<bool> specular = seesSpecular(scene);
    std::vector<bool> clear(specular.size(), true);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < 32 && yy < 32 && specular[size_t(yy) * 32 + xx])
                        clear[size_t(y) * 32 + x] = false;
                }
    const ps::stats::ZTestResult z = ps::stats::zTestImages(select(r.mean, clear), select(r.variance, clear),
                                                            select(ref, clear), select(refVar, clear), alpha());
    CHECK_MESSAGE(z.passed, "bpt on cornell-spheres (32 x 32, maxdepth 8, "
                                << kIterations << " spp, seed " << kSeedSpheres
                                << "), the pixels away from the spheres: expected the "
                                   "path-traced reference within its noise (x is the index "
                                   "among those pixels: a = yours, b = the reference), got\n  "
                                << z.report);
    const double mine = total(select(r.mean, specular)), theirs = total(select(ref, specular));
    CHECK_MESSAGE(std::abs(mine - theirs) <= 0.1 * theirs,
                  "bpt on cornell-spheres, the pixels that see a sphere: expected the sum of "
                  "their values to be the reference's "
                      << num(theirs) << " +- 10 %, got " << num(mine));
}

TEST_CASE("bpt equals the path-traced reference with a point light: no s = 0 technique (z-test) [2 pts]") {
    checkAgainstReference({"cornell-point-light", "tests/07-bidirectional/data/cornell-point-light-32", 256}, "bpt",
                          7104);
}

TEST_CASE("bpt equals the path-traced reference with a background light: vertices at infinity (z-test) [2 pts]") {
    checkAgainstReference({"cornell-background", "tests/07-bidirectional/data/cornell-background-32", 256}, "bpt",
                          7105);
}
