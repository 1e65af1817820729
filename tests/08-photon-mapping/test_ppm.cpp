// Lesson 8, graded: progressive photon mapping (Eq. 8.13-8.14).
// Exact: the radius of pass n from Eq. 8.13 against its closed form r_1^2 Gamma(n + alpha) /
// (Gamma(1 + alpha) Gamma(n + 1)) ~ r_1^2 n^(alpha - 1) / Gamma(1 + alpha).
// A stated bound: the passes of ppm on the Cornell box (32 x 32, the pixels that see the lamp left
// out) against the reference of lessons 3 and 7 (262144 spp of pt, which lesson 7's tests show
// bpt equals): the relMSE of the average of the first n passes must fall at every doubling of n
// and be at most kFinalBound after 64 passes. The test renders the passes as `ppm` does
// (ppm_integrator.cpp), with a first radius of 0.06 R (R the scene's bounding radius) and 4096
// photon paths a pass, so that the bias matters: with the radius kept constant the error levels
// off at the bias (0.0105 ... 0.0120 over 30 seeds), with Eq. 8.13 it ends at 0.0042 ... 0.0054
// (30 seeds; the largest of the six ratios between successive checkpoints was 0.74 ... 0.89 per
// seed). The bound 0.0075 lies between the two with a margin of 1.4 on each side. (The factor of
// Eq. 8.13 applied to r instead of r^2 shrinks the radius faster and ends lower, 0.0026 ... 0.0029:
// the radius test catches that.) Statistical (at level alpha(), lesson08.h): the pixels that see
// the lamp, left out of the error, must hold the reference's sum within 5 % plus the noise of the
// 64 passes (the emission seen directly).
#include <omp.h>
#include <cmath>
#include "image.h"
#include "lesson08.h"
#include "tasks.h"

using namespace lesson08;

namespace {

// The closed form of r_n^2 / r_1^2 (Eq. 8.13 applied n - 1 times).
double radiusRatioClosedForm(int n, double alpha) {
    return std::exp(std::lgamma(n + alpha) - std::lgamma(1.0 + alpha) - std::lgamma(n + 1.0));
}

// relMSE = mean over channels of (x - r)^2 / (r^2 + 0.01) (the render command's), over the
// pixels not in `skip`.
double relMSE(const std::vector<double>& sum, int passes, const ps::Image& ref, const std::vector<bool>& skip) {
    double s = 0.0;
    int n = 0;
    for (size_t i = 0; i < ref.pixels.size(); ++i) {
        if (skip[i]) continue;
        for (int c = 0; c < 3; ++c) {
            const double x = sum[i * 3 + size_t(c)] / passes, r = ref.pixels[i][c];
            s += (x - r) * (x - r) / (r * r + 0.01);
            ++n;
        }
    }
    return s / n;
}

}  // namespace

TEST_CASE("ppm: the radius update shrinks r^2 by (i + alpha) / (i + 1) every pass (Eq. 8.13) [1 pt]") {
    for (double alpha : {ps::kPpmAlpha, 0.5, 0.9}) {
        const double r1sq = 2.5;
        double r2 = r1sq;
        std::vector<double> ratio(10001, 0.0);  // r_n^2 / r_1^2, n = 1 .. 10000
        ratio[1] = 1.0;
        for (int n = 1; n < 10000; ++n) {
            r2 = ps::ppmNextRadius2(r2, n, alpha);
            ratio[size_t(n) + 1] = r2 / r1sq;
        }
        const double first = ratio[2];
        // The exponent r_n^2 falls with, from n = 1000 to 10000 (alpha - 1 for Eq. 8.13).
        const double exponent = std::log(ratio[10000] / ratio[1000]) / std::log(10.0);
        std::string hint;
        if (ratio[10000] == 1.0) hint = " (the radius never shrinks: the update returns r^2 as it is)";
        else if (ratio[10000] > 1.0) hint = " (the radius grows: (i + 1) / (i + alpha) turned over?)";
        else if (std::abs(exponent - 2.0 * (alpha - 1.0)) < 0.02)
            hint = " (r^2 falls like n^(2 (alpha - 1)): the factor (i + alpha) / (i + 1) applied to r, not to r^2?)";
        else if (std::abs(first - alpha) < 1e-9)
            hint = " (the first pass shrinks by alpha: the pass counted from 0, not from 1?)";
        else if (std::abs(exponent) > 1.5)
            hint = " (the radius shrinks geometrically: the factor must tend to 1 as the passes go on)";
        for (int n : {2, 3, 10, 100, 1000, 10000}) {
            const double expected = radiusRatioClosedForm(n, alpha);
            CHECK_MESSAGE(std::abs(ratio[size_t(n)] / expected - 1.0) < 1e-9,
                          "alpha = " << num(alpha) << ": expected r_" << n << "^2 / r_1^2 = Gamma(n + alpha) / "
                                     << "(Gamma(1 + alpha) Gamma(n + 1)) = " << num(expected) << ", got "
                                     << num(ratio[size_t(n)]) << "; r_2^2 / r_1^2 = " << num(first) << " (expected "
                                     << num((1.0 + alpha) / 2.0) << "), r^2 falls like n^" << num(exponent)
                                     << " (expected n^(alpha - 1) = n^" << num(alpha - 1.0) << ")" << hint);
        }
    }
}

TEST_CASE(
    "ppm: on the Cornell box the error against the bpt reference falls pass after pass and ends under the bound "
    "(Eq. 8.13, 8.14) [3 pts]") {
    omp_set_num_threads(1);  // tiny images: one thread is faster; the result does not depend on it
    constexpr int kPasses = 64, kPhotons = 4096, w = 32, h = 32;
    constexpr double kFirstRadius = 0.06, kFinalBound = 0.0075;
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", w, h);
    const ps::Image ref = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm"));
    const std::vector<bool> skip = pixelsSeeingLights(scene);
    const double r1 = kFirstRadius * scene.radius;
    const uint64_t seed = ps::testseed::seed(841);
    const int maxDepth = scene.settings.maxDepth;
    std::vector<double> sum(size_t(w * h) * 3, 0.0);
    std::vector<int> checkpoints;
    std::vector<double> errors;
    ps::stats::Welford lamp;  // each pass's mean over the pixels that see the lamp
    ps::SampleStats stats;
    for (int pass = 1; pass <= kPasses; ++pass) {
        const float r2 = float(ps::ppmRadius2(r1 * r1, pass));
        const PhotonMap map = ps::tracePhotonMap(scene, ps::MapKind::Global, kPhotons, maxDepth, seed ^ 0x5DEECE66Dull,
                                                 uint32_t(pass - 1), stats);
        ps::Image img(w, h);
        ps::renderPixelTasks(seed, uint32_t(pass - 1), img, stats, false, [&](int pixel, ps::Rng& rng, ps::Task&) {
            const ps::Ray ray = scene.camera.generateRay(ps::jitteredRaster(pixel, w, rng));
            return ps::LiProgressive(scene, ray, rng, map, r2, maxDepth);
        });
        double lampSum = 0.0;
        for (size_t i = 0; i < img.pixels.size(); ++i) {
            for (int c = 0; c < 3; ++c) sum[i * 3 + size_t(c)] += img.pixels[i][c];
            if (skip[i]) lampSum += ps::testrender::sum(img.pixels[i]);
        }
        lamp.add(lampSum);
        if ((pass & (pass - 1)) == 0) {
            checkpoints.push_back(pass);
            errors.push_back(relMSE(sum, pass, ref, skip));
        }
    }
    CHECK_MESSAGE(stats.bad() == 0, "ppm on the Cornell box: expected 0 NaN and 0 Inf samples, got "
                                        << stats.nan << " NaN and " << stats.inf << " Inf");
    // The lamp seen directly: its pixels' sum within 5 % of the reference's, plus the noise.
    double lampRef = 0.0;
    for (size_t i = 0; i < ref.pixels.size(); ++i)
        if (skip[i]) lampRef += ps::testrender::sum(ref.pixels[i]);
    const double lampNoise = zCritical() * std::sqrt(lamp.variance() / kPasses);
    MESSAGE("ppm, the pixels that see the lamp: " << num(lamp.mean) << " against the reference's " << num(lampRef)
                                                  << " (noise " << num(lampNoise) << ")");
    CHECK_MESSAGE(std::abs(lamp.mean - lampRef) <= 0.05 * lampRef + lampNoise,
                  "ppm on the Cornell box, the pixels that see the lamp: expected their sum "
                      << num(lampRef) << " (the reference's) within 5 % + noise " << num(lampNoise) << ", got "
                      << num(lamp.mean)
                      << (lamp.mean < 0.5 * lampRef ? " (the emission seen directly is missing)" : ""));
    std::string table;
    for (size_t i = 0; i < errors.size(); ++i) table += " " + std::to_string(checkpoints[i]) + ": " + num(errors[i]);
    MESSAGE("ppm, relMSE after n passes:" << table);
    for (size_t i = 1; i < errors.size(); ++i)
        CHECK_MESSAGE(errors[i] < errors[i - 1], "ppm on the Cornell box: expected the error to fall from "
                                                     << checkpoints[i - 1] << " to " << checkpoints[i]
                                                     << " passes, got relMSE " << num(errors[i - 1]) << " then "
                                                     << num(errors[i]) << " (n: relMSE" << table << ")");
    const double last = errors.back(), fall = errors.back() / errors[errors.size() - 4];
    std::string hint;
    if (errors.front() > 0.5) hint = " (far off from the first pass on: is the estimate black, or a factor off?)";
    else if (fall > 0.6)
        hint = " (the error levels off: over the last three doublings it fell only to " + num(fall) +
               " of what it was (Eq. 8.13: about 0.3); the bias stays: does the radius shrink?)";
    CHECK_MESSAGE(last <= kFinalBound, "ppm on the Cornell box, "
                                           << kPasses << " passes: expected relMSE <= " << num(kFinalBound) << ", got "
                                           << num(last) << " (n: relMSE" << table << ")" << hint);
}

TEST_CASE("ppm and pm-ic: the images and the irradiance cache do not depend on the number of threads [1 pt]") {
    // The mirror scene at 16 x 16, 3 iterations, with 1 and 2 threads: identical bits, not black.
    // ppm's radius depends on the pass alone (Eq. 8.13); the cache is filled coarse to fine with
    // the records of a level appended in pixel order (irradiance_cache_fill.cpp). Neither holds
    // if a piece keeps state between calls or shares a generator.
    const ps::Scene scene = loadSceneAt("tests/08-photon-mapping/data/mirror-floor.scene", 16, 16);
    for (const char* algo : {"ppm", "pm-ic"}) {
        const ps::testrender::Render one = ps::testrender::render(scene, algo, 3, ps::testseed::seed(842), 1);
        const ps::testrender::Render two = ps::testrender::render(scene, algo, 3, ps::testseed::seed(842), 2);
        REQUIRE_MESSAGE(ps::testrender::total(one.mean) > 0.0, algo << " on the mirror scene renders black");
        size_t differ = 0;
        for (size_t i = 0; i < one.mean.pixels.size(); ++i) differ += one.mean.pixels[i] != two.mean.pixels[i];
        CHECK_MESSAGE(differ == 0, algo << ", mirror scene, 3 iterations: " << differ
                                        << " pixels differ between 1 and 2 threads; expected identical bits");
    }
    ps::SampleStats stats;
    const PhotonMap global = ps::tracePhotonMap(scene, ps::MapKind::Global, 4000, 8, ps::testseed::seed(843), 0, stats);
    ps::PmOptions opt;
    opt.globalEstimate.maxRadius = 0.1f * scene.radius;
    opt.gatherSide = 4;
    opt.minR = 0.03f * scene.radius;
    opt.maxR = 0.5f * scene.radius;
    omp_set_num_threads(1);
    const ps::IrradianceCache a = ps::buildIrradianceCache(scene, global, opt, 0.2f, 16, 16, 7, 0, stats);
    omp_set_num_threads(2);
    const ps::IrradianceCache b = ps::buildIrradianceCache(scene, global, opt, 0.2f, 16, 16, 7, 0, stats);
    bool same = a.records.size() == b.records.size() && !a.records.empty();
    for (size_t i = 0; same && i < a.records.size(); ++i)
        same = a.records[i].p == b.records[i].p && a.records[i].E == b.records[i].E && a.records[i].R == b.records[i].R;
    CHECK_MESSAGE(same, "irradiance cache of the mirror scene: " << a.records.size() << " and " << b.records.size()
                                                                 << " records with 1 and 2 threads; expected the same "
                                                                    "records in the same order (and some)");
}
