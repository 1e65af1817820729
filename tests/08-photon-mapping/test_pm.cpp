// Lesson 8, graded: the `pm` integrator (Eq. 8.11) against the path-traced Cornell box (lesson
// 3's stored reference, 32 x 32, maxdepth 8). Photon mapping is biased (README, "Bias"), so the
// test states a bound: the image's mean, and the mean of each quadrant, must be within 1.5 % (3 %
// for a quadrant; pm-ic 2 % and 4 %) of the reference, plus the noise at level alpha() (lesson08.h).
// The bias measured with the reference solution is -0.1 .. +0.9 % on the image and -1 .. +2.3 % on
// the quadrants:
// the k-nearest box estimate's k / (k - 1) = +2 % on the indirect light (about a third of the
// image), the disc assumption at the box's edges and corners, and photon paths that go on for up to
// maxdepth bounces after the gather point (the reference stops at 8; in this box the light of
// longer paths is below 1 %). A missing term (direct light, final gathering) or a factor pi is
// far outside. Each iteration traces new photon maps, so the iterations' means are independent:
// their spread is the noise (pixels of one iteration share the maps and are not independent).
#include <omp.h>
#include "integrator.h"
#include "image.h"
#include "lesson08.h"

using namespace lesson08;

namespace {

// Renders `iterations` iterations of `algo` on the Cornell box at 32 x 32 and compares the mean of
// the image and of each quadrant, without the lamp's pixels, with lesson 3's reference: within
// the bias bound (imageBound, quadrantBound: fractions of the reference) plus the noise at level
// alpha() (the spread of the iterations' means and the reference's standard error).
void checkCornell(const std::string& algo, int iterations, uint64_t seed, double imageBound, double quadrantBound) {
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 32, 32);
    const ps::Image ref = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32-variance.pfm"));
    std::unique_ptr<ps::Integrator> pm = ps::makeIntegrator(algo);
    pm->prepare(scene);
    const int w = ref.width, h = ref.height;
    // Pixels that see the lamp are left out: a pixel on its edge is 100 times brighter in some
    // samples than in others, noise that 16 iterations cannot average and that says nothing about
    // photon mapping.
    const std::vector<bool> seesLamp = pixelsSeeingLights(scene);
    // Regions: the whole image, then the four quadrants, without the lamp's pixels.
    auto inRegion = [&](int region, int x, int y) {
        if (seesLamp[size_t(y) * w + x]) return false;
        if (region == 0) return true;
        const int q = region - 1;
        return (x >= w / 2) == bool(q & 1) && (y >= h / 2) == bool(q & 2);
    };
    const char* names[5] = {"the whole image (without the lamp)", "the top left quadrant", "the top right quadrant",
                            "the bottom left quadrant", "the bottom right quadrant"};
    ps::stats::Welford mean[5];
    ps::stats::ImageWelford images;  // for the images a failure writes
    ps::SampleStats stats;
    for (int it = 0; it < iterations; ++it) {
        ps::Image img(w, h);
        pm->renderIteration(scene, uint32_t(it), seed, img, stats);
        images.add(img);
        for (int region = 0; region < 5; ++region) {
            double s = 0.0;
            int n = 0;
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x)
                    if (inRegion(region, x, y)) {
                        s += ps::testrender::sum(img.pixels[size_t(y * w + x)]);
                        ++n;
                    }
            mean[region].add(s / n);
        }
    }
    CHECK_MESSAGE(stats.bad() == 0, algo << " on the Cornell box: expected 0 NaN and 0 Inf samples, got " << stats.nan
                                         << " NaN and " << stats.inf << " Inf");
    for (int region = 0; region < 5; ++region) {
        double r = 0.0, rv = 0.0;
        int n = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (inRegion(region, x, y)) {
                    r += ps::testrender::sum(ref.pixels[size_t(y * w + x)]);
                    rv += ps::testrender::sum(refVar.pixels[size_t(y * w + x)]);
                    ++n;
                }
        r /= n;
        // Pixels of the path-traced reference are independent; its three channels are not:
        // Var(r + g + b) <= 3 (Var r + Var g + Var b).
        const double refSe = std::sqrt(3.0 * rv) / n;
        const double fraction = region == 0 ? imageBound : quadrantBound, bound = fraction * r;
        const double noise = zCritical() * std::sqrt(mean[region].variance() / iterations + refSe * refSe);
        const double diff = mean[region].mean - r;
        std::string hint;
        const double ratio = mean[region].mean / r;
        if (ratio < 0.85) hint = " (too dark: direct light, final gathering or the global map's estimate missing?)";
        else if (ratio > 1.15)
            hint =
                " (too bright: light counted twice, e.g. emission at the gather point, or a "
                "missing 1 / pi in the estimate?)";
        MESSAGE(algo << " / reference, " << names[region] << ": " << num(ratio) << " (noise " << num(noise / r) << ", "
                     << algo << " se " << num(std::sqrt(mean[region].variance() / iterations) / r) << ", reference se "
                     << num(refSe / r) << ")");
        CHECK_MESSAGE(std::abs(diff) <= bound + noise,
                      algo << ", " << iterations << " iterations, " << names[region] << ": expected the mean " << num(r)
                           << " of the path-traced reference within the bias bound " << num(bound) << " ("
                           << num(100.0 * fraction) << " %) + noise " << num(noise) << ", got "
                           << num(mean[region].mean) << " (ratio " << num(ratio) << ")" << hint << "\n  "
                           << ps::stats::writeFailedImages(images.mean(), images.varianceOfMean(), ref, refVar));
    }
}

}  // namespace

TEST_CASE(
    "pm: the photon-mapped Cornell box agrees with the path-traced reference within the stated bias bound (Eq. 8.11) [3 pts]") {
    // Bounds (issue 28: at the measured bias, not above it): the image 1.5 %, a quadrant 3 %, plus
    // the noise at alpha() (2.2-2.9 % on the image here). Measured with the reference solution,
    // PATHSPACE_TEST_SEED 0-5: the image -0.1 ... +0.7 %, the quadrants -1.0 ... +2.2 %.
    checkCornell("pm", 16, ps::testseed::seed(831), 0.015, 0.03);
}

TEST_CASE(
    "pm-ic: with the irradiance cache the Cornell box agrees with the path-traced reference within the stated bias "
    "bound (Eq. 8.11, 8.17) [2 pts]") {
    // The cache's interpolation adds its own bias: bounds 2 % and 4 % (measured, seeds 0-5: the
    // image +0.7 ... +1.1 %, the quadrants -1.6 ... +3.0 %), plus the noise at alpha().
    checkCornell("pm-ic", 8, ps::testseed::seed(834), 0.02, 0.04);
}

TEST_CASE("pm: the image and the photon maps do not depend on the number of threads [1 pt]") {
    // The mirror scene at 16 x 16 (a caustic map and a global map), 2 iterations, with 1 and 2
    // threads: identical bits, not black. The photon pass runs in the framework's task loop (path i
    // draws from its own generator, photons joined in path order), so this holds by construction
    // unless a piece keeps state between calls or shares a generator.
    const ps::Scene scene = loadSceneAt("tests/08-photon-mapping/data/mirror-floor.scene", 16, 16);
    const ps::testrender::Render one = ps::testrender::render(scene, "pm", 2, ps::testseed::seed(832), 1);
    const ps::testrender::Render two = ps::testrender::render(scene, "pm", 2, ps::testseed::seed(832), 2);
    REQUIRE_MESSAGE(ps::testrender::total(one.mean) > 0.0, "pm on the mirror scene renders black");
    size_t differ = 0;
    for (size_t i = 0; i < one.mean.pixels.size(); ++i) differ += one.mean.pixels[i] != two.mean.pixels[i];
    CHECK_MESSAGE(differ == 0, "pm, mirror scene, 2 iterations: " << differ
                                                                  << " pixels differ between 1 and 2 threads; expected "
                                                                     "identical bits (framework/tasks.h)");
    for (ps::MapKind kind : {ps::MapKind::Global, ps::MapKind::Caustic}) {
        ps::SampleStats s1, s2;
        omp_set_num_threads(1);
        const PhotonMap a = ps::tracePhotonMap(scene, kind, 3000, 8, ps::testseed::seed(833), 0, s1);
        omp_set_num_threads(2);
        const PhotonMap b = ps::tracePhotonMap(scene, kind, 3000, 8, ps::testseed::seed(833), 0, s2);
        bool same = a.size() == b.size() && a.size() > 0;
        for (size_t i = 1; same && i <= a.size(); ++i)
            same = a.nodes[i].p == b.nodes[i].p && a.nodes[i].power == b.nodes[i].power;
        CHECK_MESSAGE(same, (kind == ps::MapKind::Global ? "global" : "caustic")
                                << " map of 3000 photon paths: different (or empty) with 1 and 2 threads");
    }
}

TEST_CASE(
    "pm: the caustic of the Cornell spheres' glass sphere is on the floor, as bright as in the path-traced reference "
    "(Eq. 8.11) [2 pts]") {
    // The glass sphere focuses the lamp's light on the floor (paths L S S D E): only the caustic
    // map carries it (final gathering sees the glass and stops). The caustic's pixels are taken
    // from the reference alone: pixels that see only the floor and are more than 1.5 times as
    // bright as the floor's median. Their mean must be within 10 % of the reference's (the
    // k-nearest estimate blurs a caustic a few pixels wide: measured 0.97-0.99 of the reference
    // over PATHSPACE_TEST_SEED 0-5; the bound was 25 % before issue 28), plus the noise at level
    // alpha() (about 15 % here: 4 pixels, 256 iterations).
    const ps::Scene scene = loadSceneAt("scenes/cornell-spheres.scene", 32, 32);
    const ps::Image ref = ps::readPFM(sourcePath("tests/05-light-tracing/data/cornell-spheres-32.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/05-light-tracing/data/cornell-spheres-32-variance.pfm"));
    const int w = ref.width, h = ref.height;
    const std::vector<bool> floor = ps::testrender::pixelsWhere(
        scene, true, [](bool hit, const ps::SurfacePoint& sp) { return hit && sp.p.y <= 1.0f && sp.n.y >= 0.99f; });
    std::vector<double> floorValues;
    for (size_t p = 0; p < floor.size(); ++p)
        if (floor[p]) floorValues.push_back(ps::testrender::sum(ref.pixels[p]));
    REQUIRE(floorValues.size() > 20);
    std::nth_element(floorValues.begin(), floorValues.begin() + floorValues.size() / 2, floorValues.end());
    const double median = floorValues[floorValues.size() / 2];
    std::vector<size_t> caustic;
    double r = 0.0, rv = 0.0;
    for (size_t p = 0; p < floor.size(); ++p)
        if (floor[p] && ps::testrender::sum(ref.pixels[p]) > 1.5 * median) {
            caustic.push_back(p);
            r += ps::testrender::sum(ref.pixels[p]);
            rv += ps::testrender::sum(refVar.pixels[p]);
        }
    REQUIRE_MESSAGE(caustic.size() >= 3, "the test's caustic region has " << caustic.size() << " pixels");
    const double n = double(caustic.size());
    r /= n;
    const double refSe = std::sqrt(3.0 * rv) / n;
    std::unique_ptr<ps::Integrator> pm = ps::makeIntegrator("pm");
    pm->prepare(scene);
    ps::stats::Welford mean;
    ps::stats::ImageWelford images;  // for the images a failure writes
    ps::SampleStats stats;
    const int iterations = 256;
    for (int it = 0; it < iterations; ++it) {
        ps::Image img(w, h);
        pm->renderIteration(scene, uint32_t(it), ps::testseed::seed(835), img, stats);
        images.add(img);
        double s = 0.0;
        for (size_t p : caustic) s += ps::testrender::sum(img.pixels[p]);
        mean.add(s / n);
    }
    CHECK_MESSAGE(stats.bad() == 0, "pm on the Cornell spheres: expected 0 NaN and 0 Inf samples, got "
                                        << stats.nan << " NaN and " << stats.inf << " Inf");
    const double noise = zCritical() * std::sqrt(mean.variance() / iterations + refSe * refSe);
    const double ratio = mean.mean / r;
    MESSAGE("pm / reference in the caustic (" << caustic.size() << " pixels, floor median " << num(median)
                                              << "): " << num(ratio) << " (noise " << num(noise / r)
                                              << ", reference se " << num(refSe / r) << ")");
    CHECK_MESSAGE(std::abs(mean.mean - r) <= 0.10 * r + noise,
                  "the caustic under the glass sphere ("
                      << caustic.size() << " floor pixels): expected the mean " << num(r)
                      << " of the path-traced reference within 10 % + noise " << num(noise) << ", got "
                      << num(mean.mean) << " (ratio " << num(ratio) << ")"
                      << (ratio < 0.75 ? " (too dark: is the caustic map looked up "
                                         "at the diffuse point after a specular "
                                         "bounce?)"
                                       : "")
                      << "\n  " << ps::stats::writeFailedImages(images.mean(), images.varianceOfMean(), ref, refVar));
}
