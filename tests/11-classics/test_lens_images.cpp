// Lesson 11, graded: whole images through the thin lens (Eq. 11.10-11.18), on the lens box
// (tests/11-classics/data/lens-box.scene: 16 x 16 pixels, a lens of radius 25 cm focused on the
// glossy sphere, maxdepth 3) against the stored path-traced reference next to it (262144 spp, its
// variance of the mean; rendered with the reference solutions, seed 1):
//   pt   the framework's pixel loop with your lensPoint and lensRay;
//   lt   lesson 5's light tracer: each light path joined to a lens point (lensRasterOfDirection,
//        lensWe, pdfLens through the camera's point functions);
//   bpt  lesson 7's bidirectional path tracer with t = 1 through the camera subpath's lens point
//        and the new t = 0 (your connectLens), MIS-weighted (Eq. 11.18).
// Per-pixel z-tests at level alpha() (lens_support.h): each of the 768 pixel channels at the Sidak
// level of alpha() over the channels, at least 99.75 % must pass.
// Then t = 0 alone: for path lengths 1-3 its unweighted estimate equals s = 0's (the camera path
// that hits the light), per pixel and in total, and it is not zero; and the MIS weights of every
// technique, t = 0 included, equal the power and balance heuristics of lesson 6's densities.
#include <tuple>
#include "lens_support.h"
#include "render.h"
#include "tasks.h"

using namespace lens11;

namespace {

constexpr const char* kScene = "tests/11-classics/data/lens-box.scene";

ps::Scene lensBox() { return ps::loadScene(sourcePath(kScene)); }

// The lens box's text with a lens of radius 0.4 instead of 0.25 (2.6 times as many light paths hit
// it), and `extra` lines.
ps::Scene wideLensBox(const std::string& extra, const std::string& name) {
    std::string text = ps::testfiles::readText(sourcePath(kScene));
    const size_t at = text.find("lens 0.25");
    REQUIRE_MESSAGE(at != std::string::npos, "test set-up: no 'lens 0.25' in " << kScene);
    text.replace(at, 9, "lens 0.4");
    return ps::parseScene(text + extra, name);
}

void checkAgainstReference(const std::string& algo, int spp, uint64_t seed, const std::string& hint) {
    const ps::Scene scene = lensBox();
    const ps::Image ref = ps::readPFM(sourcePath("tests/11-classics/data/lens-box-pt.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/11-classics/data/lens-box-pt-variance.pfm"));
    const ps::testrender::Render r = ps::testrender::render(scene, algo, spp, ps::testseed::seed(seed));
    CHECK_MESSAGE(r.stats.bad() == 0, algo << " through the lens: expected 0 NaN and 0 Inf samples, got " << r.stats.nan
                                           << " NaN and " << r.stats.inf << " Inf");
    const ps::stats::ZTestResult z = ps::stats::zTestImages(r.mean, r.variance, ref, refVar, alpha());
    CHECK_MESSAGE(z.passed, algo << " on the lens box (16 x 16, lens radius 0.25, maxdepth 3, " << spp
                                 << " spp): expected the stored pt reference within its noise (a = yours, b = the "
                                    "reference; image total "
                                 << num(ps::testrender::total(r.mean)) << " against " << num(ps::testrender::total(ref))
                                 << "), got\n  " << z.report << "\n  " << hint);
}

}  // namespace

TEST_CASE("lens box: pt through your lens rays converges to the stored reference (z-test) [1 pt]") {
    checkAgainstReference("pt", 1024, 1101,
                          "pt's rays come from your lensPoint and lensRay (the framework's pixel loop): a lens point "
                          "not on the disk or rays not through the point of focus blur the image wrongly");
}

TEST_CASE("lens box: lt, each light path joined to a lens point, converges to the stored reference (z-test) [2 pts]") {
    checkAgainstReference("lt", 1024, 1102,
                          "lt joins each light path to a lens point z with lesson 5's connectToCamera: raster "
                          "position lensRasterOfDirection(z, ...), importance width * height * lensWe(z, ...) over "
                          "the lens point's density pdfLens()");
}

TEST_CASE("lens box: bpt with t = 0 converges to the stored reference (z-test) [2 pts]") {
    checkAgainstReference("bpt", 256, 1103,
                          "bpt adds t = 0 (connectLens) to every other technique, weighted by MIS (Eq. 11.18); a "
                          "wrong value or raster in connectLens, or a wrong lensWe, lensPdfDirection or pdfLens, "
                          "shows here");
}

namespace {

// Per pixel sample, what each technique (s, t) of each path length k gave (t = 0 and s = 0), as
// one number (its sum over the image; t = 0 scaled like every splat) and as images.
struct Totals : ps::TechniqueRecorder {
    int maxLength = 3;
    std::vector<double> sample;  // this pixel sample's sums, per (k, kind): index 2 (k - 1) + (t == 0)
    int hits = 0;                // t = 0 contributions
    void add(int s, int t, const Vec2&, const Color& unweighted, const Color&) override {
        const int k = s + t - 1;
        if (k < 1 || k > maxLength || (s != 0 && t != 0)) return;
        sample[size_t(2 * (k - 1) + (t == 0))] += ps::testrender::sum(unweighted);
        if (t == 0) ++hits;
    }
};

}  // namespace

TEST_CASE(
    "lens box: bpt's t = 0 technique alone is unbiased and contributes: per path length its unweighted estimate "
    "equals s = 0's (z-tests) [2 pts]") {
    // Image totals from every pixel sample of ps::bptSample (independent samples: the t = 0
    // splats of one light subpath belong to its pixel sample) and per-pixel images from lesson
    // 7's per-technique images; each comparison at sidak(alpha(), 6), the test at alpha().
    const ps::Scene scene = wideLensBox("", "lens box, lens radius 0.4");
    const int spp = 768, w = scene.camera.width(), h = scene.camera.height();
    Totals totals;
    std::vector<ps::stats::Welford> est(6);
    ps::BptOptions opt;
    ps::SplatTarget none;  // splats dropped: the recorder sees them
    none.scale = 1.0f / float(w * h);
    const uint64_t seed = ps::testseed::seed(1104);
    for (int it = 0; it < spp; ++it)
        for (int pixel = 0; pixel < w * h; ++pixel) {
            ps::Rng rng = ps::taskRng(seed, uint32_t(it), uint32_t(pixel));
            totals.sample.assign(6, 0.0);
            const Vec2 raster = ps::jitteredRaster(pixel, w, rng);
            (void)ps::bptSample(scene, raster, rng, opt, none, &totals);
            for (size_t i = 0; i < 6; ++i) est[i].add(totals.sample[i]);
        }
    const double level = ps::stats::sidak(alpha(), 6);
    CHECK_MESSAGE(totals.hits >= 5000, "t = 0: expected at least 5000 light paths to hit the lens in "
                                           << spp * w * h << " pixel samples (a lens of radius 40 cm, 1-2 m away), got "
                                           << totals.hits << " (connectLens)");
    for (int k = 1; k <= 3; ++k) {
        const ps::stats::Welford &s0 = est[size_t(2 * (k - 1))], &t0 = est[size_t(2 * (k - 1) + 1)];
        const double se = std::sqrt(s0.stdError() * s0.stdError() + t0.stdError() * t0.stdError());
        const double z = (t0.mean - s0.mean) / se, p = ps::stats::normalTwoSided(z);
        // Power: the comparison resolves 5 % of the expected value.
        CHECK_MESSAGE(se <= 0.05 * s0.mean, "path length " << k << ": the comparison's standard error " << num(se)
                                                           << " is above 5 % of s = 0's estimate " << num(s0.mean)
                                                           << " (t = 0 too noisy to test)");
        CHECK_MESSAGE(t0.mean > 0.0, "path length " << k << ": t = 0 added nothing (expected about " << num(s0.mean)
                                                    << " per pixel sample, summed over the image)");
        CHECK_MESSAGE(p >= level, "path length " << k << ": t = 0 alone (unweighted) gives " << num(t0.mean)
                                                 << " per pixel sample (summed over the image), s = 0 alone "
                                                 << num(s0.mean) << ": z = " << num(z, 4) << ", p = " << num(p, 3)
                                                 << " < " << num(level, 3)
                                                 << ". Both estimate the same paths; t = 0's value is beta' * width * "
                                                    "height * W_e(z), splatted with 1 / (width * height)");
    }
    // Per pixel: the per-technique images (lesson 7's pyramid).
    const ps::TechniqueImages img = ps::renderTechniques(scene, 3, 256, ps::testseed::seed(1105), 1, opt);
    for (int k = 1; k <= 3; ++k) {
        const size_t t0 = size_t(ps::techniqueIndex(k + 1, k)), s0 = size_t(ps::techniqueIndex(0, k));
        const ps::stats::ZTestResult zt = ps::stats::zTestImages(img.unweighted[t0], img.unweightedSq[t0],
                                                                 img.unweighted[s0], img.unweightedSq[s0], level);
        CHECK_MESSAGE(zt.passed,
                      "path length " << k << ": the image of t = 0 alone (a) against s = 0 alone (b): " << zt.report);
    }
}

namespace {

constexpr double kRelTol = 1e-3, kAbsTol = 1e-6;
constexpr int kSamples = 1000;  // pixel samples per heuristic

// The joined path of technique (s, t) as lesson 6's Path; t = 0: lensMisWeight's path.
ps::Path joinedPath(const ps::PathVertex* y, int s, const ps::Subpath& camera, int t) {
    ps::Path x(y, y + s);
    for (int k = t - 1; k >= 0; --k) x.push_back(camera[size_t(k)]);
    return x;
}

}  // namespace

TEST_CASE(
    "lens box: MIS weights with t = 0 equal the power and balance heuristics of lesson 6's densities, t = 0 "
    "included (Eq. 11.18) [2 pts]") {
    // On every valid connection of 1000 pixel samples (per heuristic) of the lens box (lens radius
    // 0.4) with a mirror sphere added, an area light, a point light and a background: bpt's weight of the technique that made
    // the path (t = 0: lensMisWeight; t >= 1: misWeightFull and misWeightRecursive) against
    //   w_s = p_s^b / sum_{s'} p_{s'}^b,  p_{s'} = pdfTechnique(scene, x, s') (lesson 6, s' = 0 .. n),
    // where p_n (t' = 0) is now > 0: the lens can be hit. Relative 1e-3 (+ 1e-6).
    const ps::Scene scene = wideLensBox(
        "pointlight position 0.7 0.8 0.3  intensity 0.4 0.4 0.4\nbackground radiance 0.05 0.06 0.08\n"
        "material chrome mirror albedo 0.9 0.9 0.9\nsphere center 0.72 0.15 0.4  radius 0.15  material chrome\n",
        "lens box (lens radius 0.4) with a mirror sphere, a point light and a background");
    const int w = scene.camera.width(), h = scene.camera.height(), maxDepth = scene.settings.maxDepth;
    int checked = 0, lensPaths = 0, withT0 = 0, specular = 0, failures = 0;
    for (const ps::Heuristic heur : {ps::Heuristic::Power, ps::Heuristic::Balance}) {
        const double b = heur == ps::Heuristic::Power ? 2.0 : 1.0;
        ps::Subpath camera, light;
        for (int i = 0; i < kSamples; ++i) {
            ps::Rng rng(ps::testseed::seed(1106), uint64_t(i));
            const Vec2 raster{rng.uniform() * float(w), rng.uniform() * float(h)};
            ps::cameraSubpath(scene, rng, raster, maxDepth, heur, camera);
            ps::lightSubpath(scene, rng, maxDepth, heur, light);
            // (s, t) with the weights of every form, then t = 0.
            std::vector<std::tuple<ps::Path, int, double, double>> paths;  // path, s, full, recursive
            for (int t = 1; t <= int(camera.size()); ++t)
                for (int s = 0; s <= std::max(int(light.size()), 1); ++s) {
                    if (s + t < 2 || (t == 1 && s == 0) || s + t - 2 > maxDepth) continue;
                    if (s > int(light.size()) && !(s == 1 && t >= 2)) continue;
                    const float uLight = rng.uniform();
                    const Vec2 uPoint = rng.uniform2();
                    const ps::Connection c = ps::connect(scene, light, camera, s, t, uLight, uPoint);
                    if (!c.valid) continue;
                    const ps::PathVertex* y = s == 1 ? &c.sampledLight : light.data();
                    paths.emplace_back(joinedPath(y, s, camera, t), s,
                                       ps::misWeightFull(y, s, camera.data(), t, c.rev, heur),
                                       ps::misWeightRecursive(y, s, camera.data(), t, c.rev, heur));
                }
            for (int m = 0; m < int(light.size()) && m <= maxDepth; ++m) {
                const ps::LensConnection c = ps::connectLens(scene, light.data(), m, rng);
                if (!c.valid) continue;
                ps::Subpath x;
                const double full = ps::lensMisWeight(scene, light, m, c, heur, false, &x);
                const double rec = ps::lensMisWeight(scene, light, m, c, heur, true);
                paths.emplace_back(ps::Path(x.begin(), x.end()), m + 2, full, rec);
            }
            for (const auto& [x, s, full, rec] : paths) {
                const int n = int(x.size());
                std::vector<double> p(size_t(n) + 1);
                for (int sp = 0; sp <= n; ++sp) p[size_t(sp)] = ps::pdfTechnique(scene, x, sp);
                if (!(p[size_t(s)] > 0.0)) continue;  // a path through the sphere's contact point (lesson 7's test)
                double sum = 0.0;
                for (const double q : p) sum += std::pow(q, b);
                const double want = std::pow(p[size_t(s)], b) / sum;
                ++checked;
                lensPaths += x.back().onCamera;
                withT0 += s == n;
                bool spec = false;
                for (const ps::PathVertex& v : x) spec = spec || v.specular;
                specular += spec;
                const double tol = kRelTol * want + kAbsTol;
                for (const auto& [got, form] : {std::pair<double, const char*>{full, "full"}, {rec, "recursive"}})
                    if (!(std::abs(got - want) <= tol) && failures++ < 4)
                        FAIL_CHECK((b == 2.0 ? "power" : "balance")
                                   << " heuristic, " << form << " form, technique s = " << s << ", t = " << n - s
                                   << " of a path of " << n << " vertices" << (spec ? " (through the mirror)" : "")
                                   << ": expected " << num(want) << " from lesson 6's densities (t' = 0's p_n = "
                                   << num(p[size_t(n)]) << "), got " << num(got)
                                   << ". The lens vertex's densities: pdfLens() from the camera side, and its "
                                      "directions' lensPdfDirection");
            }
        }
    }
    CHECK_MESSAGE(checked >= 4000, "expected at least 4000 valid connections from "
                                       << 2 * kSamples << " pixel samples, got " << checked);
    CHECK_MESSAGE(lensPaths == checked, "every joined path must end on a lens vertex (PathVertex::lens); "
                                            << checked - lensPaths << " of " << checked << " do not");
    CHECK_MESSAGE(withT0 >= 20, "expected at least 20 paths made by t = 0 (connectLens), got " << withT0);
    CHECK_MESSAGE(specular >= 20, "expected at least 20 paths through the mirror sphere, got " << specular);
    CHECK(failures == 0);
}
