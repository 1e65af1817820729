// Lesson 13, graded: VCM is consistent (Eq. 13.12, 13.13) on a caustic seen through glass.
// tests/13-vcm/data/sds-test.scene (scenes/sds-caustic.scene with a larger lamp) at 32 x 32:
// every path the camera sees passes a window pane, and the caustic of a glass ball on the floor
// is L S S D S S E, which no connection can make: there, merging does the work. The reference
// (data/sds-test-32.pfm) is a path tracer's, 262144 spp (README, "Expected output", has the
// command): unbiased, its median pixel within 0.9 % (one standard error), 3 % at worst.
//
// vcm runs 1024 iterations with a first radius of 0.04 R (18 cm, larger than the caustic: its bias
// dominates the error in the caustic's pixels) and alpha = 0.75. In the caustic's pixels (those the
// reference shows brighter than 0.4 on the floor, and their neighbours: 15 pixels):
//   - the relMSE must fall from 64 to 1024 iterations to at most kRateBound of what it was: a bias
//     that falls like r_n^2 ~ n^-0.25 gives a squared error 16^-0.5 = 0.25 of it (section 1.7);
//   - and end at most kFinalBound;
//   - the mean (the caustic's light, which a disc average moves about inside the region but neither
//     makes nor loses) must be the reference's within kBiasBound plus the noise of both at level
//     alpha() (lesson13.h).
// Measured with the reference solution over 8 seeds: the ratio 0.22 ... 0.36, the final relMSE
// 0.17 ... 0.33, the mean -3.6 ... +2.8 %; with a fixed radius (alpha = 1): the ratio 0.83 ... 1.35,
// the final relMSE 1.41 ... 1.77, the mean -8.6 ... -1.5 %; with a growing radius (alpha and
// 1 - alpha swapped): 0.52 ... 0.79, 0.72 ... 0.96, -41 ... -35 %. The bounds lie between.
// Measured again once lesson 7's light subpaths survived by the material (Eq. 7.1a), over
// PATHSPACE_TEST_SEED 0-19 (2026-11-28): the ratio 0.13 ... 0.52 (median 0.27; a late firefly in
// the caustic lifts the last relMSE of one seed to 0.33), the final relMSE 0.15 ... 0.33, the mean
// -3.4 ... +3.9 %. The rate bound is 0.65 since (0.5 failed one seed in ten); a growing radius is
// still caught by the final relMSE and the mean, a fixed one by all three.
#include <algorithm>
#include <memory>
#include "image.h"
#include "lesson13.h"
#include "render.h"

using namespace lesson13;

namespace {

// r_1 = 0.04 R at 32 x 32 pixels (VcmOptions::radiusFactor is that at 512 x 512: 0.04 x 32 / 512).
constexpr double kRadiusFactor = 0.04 * 32.0 / 512.0;
constexpr int kIterations = 1024;
constexpr double kRateBound = 0.65, kFinalBound = 0.5, kBiasBound = 0.06;

// The caustic's pixels: brighter than 0.4 in the reference on the floor (the image's lower half),
// and their eight neighbours.
std::vector<bool> causticRegion(const ps::Image& ref) {
    const int w = ref.width, h = ref.height;
    std::vector<bool> bright(size_t(w * h)), region(size_t(w * h));
    for (int y = h / 2; y < h; ++y)
        for (int x = 0; x < w; ++x) bright[size_t(y * w + x)] = ps::testrender::sum(ref.at(x, y)) / 3.0 > 0.4;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u >= 0 && v >= 0 && u < w && v < h && bright[size_t(v * w + u)])
                        region[size_t(y * w + x)] = true;
                }
    return region;
}

// relMSE = mean of (x - r)^2 / (r^2 + 0.01) over the region's pixel channels (converge's).
double relMSE(const ps::Image& x, const ps::Image& ref, const std::vector<bool>& region) {
    double s = 0.0;
    int n = 0;
    for (size_t i = 0; i < ref.pixels.size(); ++i)
        if (region[i])
            for (int c = 0; c < 3; ++c) {
                const double d = double(x.pixels[i][c]) - ref.pixels[i][c];
                s += d * d / (double(ref.pixels[i][c]) * ref.pixels[i][c] + 0.01);
                ++n;
            }
    return s / n;
}

// The mean of a region of an image (channels averaged) and its standard error from a variance
// image (each pixel's channels taken as one sample).
void regionMean(const ps::Image& img, const ps::Image& var, const std::vector<bool>& region, double& mean,
                double& stdErr) {
    double m = 0.0, v = 0.0;
    int n = 0;
    for (size_t i = 0; i < region.size(); ++i)
        if (region[i]) {
            m += ps::testrender::sum(img.pixels[i]) / 3.0;
            v += ps::testrender::sum(var.pixels[i]) / 9.0;
            ++n;
        }
    mean = m / n;
    stdErr = std::sqrt(v) / n;
}

}  // namespace

TEST_CASE(
    "VCM is consistent on a caustic seen through glass: the error falls as the radius shrinks, the mean stays "
    "within the bias bound [3 pts]") {
    const ps::Scene scene = loadSceneAt("tests/13-vcm/data/sds-test.scene", 32, 32);
    const ps::Image ref = ps::readPFM(sourcePath("tests/13-vcm/data/sds-test-32.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/13-vcm/data/sds-test-32-variance.pfm"));
    const std::vector<bool> region = causticRegion(ref);
    double refMean = 0.0, refErr = 0.0;
    regionMean(ref, refVar, region, refMean, refErr);
    ps::VcmOptions opt;
    opt.radiusFactor = kRadiusFactor;
    opt.alpha = 0.75;
    std::unique_ptr<ps::Integrator> vcm = ps::makeVcmIntegrator(opt);
    double at64 = 0.0, atEnd = 0.0, mean = 0.0, err = 0.0;
    ps::RenderOptions ro;
    ro.spp = kIterations;
    ro.seed = ps::testseed::seed(13501);
    ro.threads = 1;
    ro.checkpoint = [&](int spp, double, const ps::Film& film, const ps::SampleStats&) {
        if (spp == 64) at64 = relMSE(film.mean(), ref, region);
        if (spp != kIterations) return;
        atEnd = relMSE(film.mean(), ref, region);
        regionMean(film.mean(), film.varianceOfMean(), region, mean, err);
    };
    const ps::RenderResult r = ps::render(scene, *vcm, ro);
    const std::string where =
        "vcm on tests/13-vcm/data/sds-test.scene (32 x 32, r_1 = " + num(ps::vcmFirstRadius(opt, scene, 32 * 32)) +
        ", alpha 0.75), the caustic's " + std::to_string(int(std::count(region.begin(), region.end(), true))) +
        " pixels";
    const std::string hint =
        " (does the radius shrink as Eq. 13.12 says, with the iteration counted from 1? does the merges' weight "
        "use the radius of this iteration?)";
    CHECK_MESSAGE(atEnd <= kRateBound * at64, where << ": expected the relMSE to fall from 64 to " << kIterations
                                                    << " iterations to at most " << kRateBound << " of it, got "
                                                    << num(at64) << " -> " << num(atEnd) << " (ratio "
                                                    << num(atEnd / at64) << ")" << hint);
    CHECK_MESSAGE(atEnd <= kFinalBound, where << ": expected a relMSE of at most " << kFinalBound << " after "
                                              << kIterations << " iterations, got " << num(atEnd) << hint);
    const double z = std::sqrt(err * err + refErr * refErr) * lesson13::zCritical();
    CHECK_MESSAGE(std::abs(mean - refMean) <= kBiasBound * refMean + z,
                  where << ": expected their mean to be the reference's " << num(refMean) << " within "
                        << num(100 * kBiasBound) << " % (the bias a disc of this radius may leave) + " << num(z)
                        << " (the noise), got " << num(mean) << " (" << num(100 * (mean / refMean - 1.0)) << " %)");
    CHECK_MESSAGE(r.stats.nan + r.stats.inf == 0,
                  "vcm: " << r.stats.nan << " NaN and " << r.stats.inf << " Inf samples");
}
