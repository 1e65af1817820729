// Lesson 13, graded: the special cases of the one integrator (README, section 1.9).
//   vcm-bpt (no merging) is lesson 7's bpt: the same image, bit for bit (exact). The light
//   subpaths come from the same random numbers as bpt's (no light pass), the connections are
//   lesson 7's, and a connection's weight becomes 1 / (1 / w_bpt + eta^b M) with eta = 0: exactly
//   w_bpt, if misWeightConnection and mergeTerms stay finite and add nothing.
//   vcm-ppm at a fixed radius (alpha = 1) estimates what lesson 8's progressive photon mapping
//   estimates at that radius: both images against each other, per-pixel z-test at level alpha()
//   (lesson13.h), on an open scene (few paths longer than maxdepth, which the two cut
//   differently) with a point light, an area light seen directly, a background, a glass sphere
//   and its caustic, a mirror sphere. Lesson 8's side is made here from lesson 8's pieces
//   (tracePhotonMap, LiProgressive) with the same radius and as many photon paths as pixels.
#include <memory>
#include "film.h"
#include "integrator.h"
#include "lesson13.h"
#include "render.h"
#include "tasks.h"

using namespace lesson13;

namespace {

void checkSameBits(const std::string& file, uint64_t seed) {
    const ps::Scene scene = loadSceneAt(file, 16, 16);
    const ps::testrender::Render a = ps::testrender::render(scene, "bpt", 4, seed);
    const ps::testrender::Render b = ps::testrender::render(scene, "vcm-bpt", 4, seed);
    int differ = 0, first = -1;
    for (size_t i = 0; i < a.mean.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (a.mean.pixels[i][c] != b.mean.pixels[i][c]) {
                ++differ;
                if (first < 0) first = int(i);
            }
    CHECK_MESSAGE(ps::testrender::total(a.mean) > 0.0, file << ": bpt rendered a black image");
    CHECK_MESSAGE(differ == 0, file << " (16 x 16, 4 spp, seed " << seed << "): expected vcm-bpt's image to be bpt's "
                                    << "bit for bit, got " << differ << " pixel channels that differ, the first at "
                                    << "pixel " << first << ": bpt "
                                    << (first >= 0 ? str(a.mean.pixels[size_t(first)]) : "") << ", vcm-bpt "
                                    << (first >= 0 ? str(b.mean.pixels[size_t(first)]) : "")
                                    << " (a connection's weight with eta = 0 must be lesson 7's, Eq. 13.10)");
}

}  // namespace

TEST_CASE("without merging, vcm renders lesson 7's bpt image bit for bit [2 pts]") {
    checkSameBits("tests/13-vcm/data/open-box.scene", ps::testseed::seed(13401));
    checkSameBits("tests/13-vcm/data/pool.scene", ps::testseed::seed(13402));
    checkSameBits("scenes/cornell-glossy.scene", ps::testseed::seed(13403));
}

TEST_CASE("vcm-ppm at a fixed radius equals lesson 8's progressive photon mapping at that radius (z-test) [2 pts]") {
    const ps::Scene scene = loadSceneAt("tests/13-vcm/data/ppm-open.scene", 16, 16);
    constexpr int kIterations = 256;
    // r = 0.05 R at 16 x 16 (VcmOptions::radiusFactor is that at 512 x 512): a caustic a few radii wide.
    constexpr double kRadiusFactor = 0.05 * 16.0 / 512.0;
    const uint64_t seed = ps::testseed::seed(13404);
    const int w = scene.camera.width(), h = scene.camera.height(), n = w * h;
    // vcm-ppm, alpha = 1.
    ps::VcmOptions opt;
    opt.mode = ps::VcmMode::Ppm;
    opt.alpha = 1.0;
    opt.radiusFactor = kRadiusFactor;
    std::unique_ptr<ps::Integrator> vcm = ps::makeVcmIntegrator(opt);
    ps::RenderOptions ro;
    ro.spp = kIterations;
    ro.seed = seed;
    ro.threads = 1;
    const ps::RenderResult r = ps::render(scene, *vcm, ro);
    // Lesson 8's ppm at the same radius, pass by pass (ppm_integrator.cpp without the schedule).
    const double radius = ps::vcmFirstRadius(opt, scene, n);
    ps::Film film(w, h);
    ps::SampleStats stats;
    for (int it = 0; it < kIterations; ++it) {
        ps::Image img(w, h);
        const ps::PhotonMap map = ps::tracePhotonMap(scene, ps::MapKind::Global, n, scene.settings.maxDepth,
                                                     seed ^ 0x5BE0CD19137E2179ull, uint32_t(it), stats);
        ps::renderPixelTasks(
            seed ^ 0x1F83D9ABFB41BD6Bull, uint32_t(it), img, stats, false, [&](int pixel, ps::Rng& rng, ps::Task&) {
                const ps::Ray ray = ps::cameraRay(scene.camera, ps::jitteredRaster(pixel, w, rng), rng);
                return ps::LiProgressive(scene, ray, rng, map, float(radius * radius), scene.settings.maxDepth);
            });
        film.addIteration(img);
    }
    const ps::Image mine = r.film.mean(), mineVar = r.film.varianceOfMean();
    const ps::Image ppm = film.mean(), ppmVar = film.varianceOfMean();
    CHECK_MESSAGE(ps::testrender::total(mine) > 0.5 * ps::testrender::total(ppm),
                  "vcm-ppm: expected an image about as bright as lesson 8's ppm (sum "
                      << num(ps::testrender::total(ppm)) << "), got " << num(ps::testrender::total(mine)));
    const ps::stats::ZTestResult z = ps::stats::zTestImages(mine, mineVar, ppm, ppmVar, alpha());
    CHECK_MESSAGE(z.passed, "vcm-ppm against lesson 8's ppm on tests/13-vcm/data/ppm-open.scene (16 x 16, "
                                << kIterations << " iterations, r = " << num(radius)
                                << " fixed; a = vcm-ppm, b = lesson 8's), got\n  " << z.report);
    CHECK_MESSAGE(r.stats.nan + r.stats.inf == 0,
                  "vcm-ppm: " << r.stats.nan << " NaN and " << r.stats.inf << " Inf samples");
}

TEST_CASE("vcm's image does not depend on the number of threads [1 pt]") {
    const ps::Scene scene = loadSceneAt("tests/13-vcm/data/open-box.scene", 16, 16);
    for (const char* algo : {"vcm", "vcm-bpm", "vcm-ppm"}) {
        const ps::testrender::Render a = ps::testrender::render(scene, algo, 3, ps::testseed::seed(13405), 1);
        const ps::testrender::Render b = ps::testrender::render(scene, algo, 3, ps::testseed::seed(13405), 2);
        CHECK_MESSAGE(ps::testrender::total(a.mean) > 0.0, algo << ": a black image");
        int differ = 0;
        for (size_t i = 0; i < a.mean.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) differ += a.mean.pixels[i][c] != b.mean.pixels[i][c];
        CHECK_MESSAGE(differ == 0, algo << " on the open box (16 x 16, 3 spp): " << differ
                                        << " pixel channels differ between 1 and 2 threads");
    }
}
