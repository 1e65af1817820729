// Lesson 11, graded: distributed ray tracing, LiDistributed (Eq. 11.19). It carries the paths
// L D? (G|S)* E (lessons/11-classics/distributed.h), so it must equal the path tracer wherever
// those are all the paths there are, and carry no diffuse interreflection anywhere:
//   - a table (diffuse, lit by an area lamp, a black square casting a soft shadow on it), and a
//     glossy (Phong, exponent 20) and a mirror sphere beside it, BELOW the table's plane: the
//     table's top cannot see them, they see the lamp, the background and each other. With at most
//     2 bounces every path of the scene is L E, L D E, L G E, L S E, L G S E, L S G E, L D G E ...
//     i.e. of DRT's class (no light reaches the table's top through a sphere; its underside,
//     lit by the spheres, is seen only through them, 3 bounces): drt equals pt (z-test); and a
//     glossy floor under a lamp (every path L G E, the light sample and the glossy ray MIS-weighted);
//   - a closed diffuse box (albedo 0.7) under a lamp, maxdepth 5: drt equals direct illumination
//     only, pt with maxdepth 1 (z-test), not pt with maxdepth 5 (which is 2.3 times brighter);
//   - scenes/cornell-lens.scene, where pt carries many more paths than drt (the walls light each
//     other, the glossy and mirror spheres throw caustics): drt equals pt filtered to exactly
//     DRT's paths, `pt --paths 'LD?(G|S)*E'` (lesson 11's first part), stored as a reference.
// Reference images of the first two are rendered here by lesson 3's pt (the reference's, when
// lesson 11 is graded); the third is stored (tests/11-classics/data/, the README says how it was
// made): its classification is the reference's, never yours.
#include "lens_support.h"

using namespace lens11;

namespace {

const char* kTable = R"(
camera eye 0 1.6 3.6  target 0 -0.2 0  fov 45  resolution 18 12
material table diffuse albedo 0.7 0.7 0.7
material shade diffuse albedo 0 0 0
material gloss phong albedo 0.8 0.6 0.3 exponent 20
material chrome mirror albedo 0.9 0.9 0.9
quad -1 0 1  1 0 1  1 0 -1  -1 0 -1  material table
quad -0.2 0.6 -0.2  0.2 0.6 -0.2  0.2 0.6 0.2  -0.2 0.6 0.2  material shade
sphere center 1.5 -0.5 0  radius 0.4  material gloss
sphere center -1.5 -0.5 0  radius 0.4  material chrome
quad -0.3 2 -0.3  0.3 2 -0.3  0.3 2 0.3  -0.3 2 0.3  emission 12 12 12
background radiance 0.1 0.1 0.12
render maxdepth 2
)";

// A glossy floor (Phong, exponent 8) mirroring a lamp 0.8 above it: every path is L G E (the
// floor cannot see itself), sampled both by the light sample and by the glossy ray that hits the
// lamp; the two share it by the power heuristic (counted twice, the reflection is too bright).
const char* kGlossyFloor = R"(
camera eye 0 1 2.2  target 0 0 -0.3  fov 50  resolution 12 8
material g phong albedo 0.8 0.8 0.8 exponent 8
quad -2 0 2  2 0 2  2 0 -2  -2 0 -2  material g
quad -0.4 0.8 -0.7  0.4 0.8 -0.7  0.4 0.8 0.1  -0.4 0.8 0.1  emission 6 6 6
background radiance 0.05 0.05 0.05
render maxdepth 3
)";

const char* kClosedBox = R"(
camera eye 0.5 0.5 0.1  target 0.5 0.45 1  fov 70  resolution 8 8
material w diffuse albedo 0.7 0.7 0.7
quad 0 0 0  1 0 0  1 0 1  0 0 1  material w
quad 0 1 0  0 1 1  1 1 1  1 1 0  material w
quad 0 0 0  0 0 1  0 1 1  0 1 0  material w
quad 1 0 0  1 1 0  1 1 1  1 0 1  material w
quad 0 0 1  1 0 1  1 1 1  0 1 1  material w
quad 0 0 0  0 1 0  1 1 0  1 0 0  material w
quad 0.4 0.98 0.4  0.6 0.98 0.4  0.6 0.98 0.6  0.4 0.98 0.6  emission 20 20 20
render maxdepth 5
)";

// A mirror sphere over a diffuse floor under a lamp, at most one bounce: the floor seen through the
// mirror may not take a light sample (that path, L D S E, has two bounces), the lamp seen in the
// mirror (L S E) and the floor's own light sample (L D E) are all there is.
const char* kMirrorOverFloor = R"(
camera eye 0 1.2 2.6  target 0 0.5 0  fov 40  resolution 12 8
material floor diffuse albedo 0.7 0.7 0.7
material chrome mirror albedo 0.9 0.9 0.9
quad -3 0 3  3 0 3  3 0 -3  -3 0 -3  material floor
sphere center 0 0.6 0  radius 0.5  material chrome
quad -0.3 2.5 -0.3  0.3 2.5 -0.3  0.3 2.5 0.3  -0.3 2.5 0.3  emission 10 10 10
render maxdepth 1
)";

// The noise drt's mean is judged with, per pixel channel: drt's own variance of the mean, or the
// reference's variance per sample at drt's sample count, whichever is larger. Where the lens blurs
// the lamp's edge, a pixel sees the lamp from a few of its lens points only: a rare event that
// 1024 samples may miss altogether, leaving a mean without the lamp and a variance near 0 that no
// z-test can trust (2 false failures in 100 seeds). The reference, with 256 times the samples,
// saw those events: on the paths both carry (here the lamp seen directly, by the same camera ray)
// its variance per sample is drt's. (The per-pixel z-test of Mitsuba 3 judges every image with
// the reference's variance per sample.)
ps::Image judgedVariance(const ps::Image& variance, int spp, const ps::Image& refVariance, int refSpp) {
    ps::Image v = variance;
    const float scale = float(refSpp) / float(spp);
    for (size_t i = 0; i < v.pixels.size(); ++i) v.pixels[i] = glm::max(v.pixels[i], refVariance.pixels[i] * scale);
    return v;
}

ps::testrender::Render renderAt(const char* text, const std::string& algo, int maxDepth, int spp, uint64_t seed) {
    ps::Scene scene = ps::parseScene(text, algo + " test scene");
    if (maxDepth >= 0) scene.settings.maxDepth = maxDepth;
    return ps::testrender::render(scene, algo, spp, ps::testseed::seed(seed));
}

// drt (a) against pt (b) on the scene `text`, drt at its own maxdepth and pt at ptMaxDepth (-1:
// the scene's), seeds `seed` and seed + 1, a z-test at `level`. `what` names the comparison in the
// message and `hint` the rule it checks; `ifBlack`, if given, is the message for a black drt image.
void checkDrtAgainstPt(const char* text, int ptMaxDepth, int drtSpp, int ptSpp, uint64_t seed, double level,
                       const std::string& what, const std::string& hint, const char* ifBlack = nullptr) {
    const ps::testrender::Render drt = renderAt(text, "drt", -1, drtSpp, seed);
    const ps::testrender::Render pt = renderAt(text, "pt", ptMaxDepth, ptSpp, seed + 1);
    if (ifBlack) REQUIRE_MESSAGE(ps::testrender::total(drt.mean) > 0.0, ifBlack);
    const ps::stats::ZTestResult z = ps::stats::zTestImages(drt.mean, drt.variance, pt.mean, pt.variance, level);
    CHECK_MESSAGE(z.passed, "drt (a) against pt (b) "
                                << what << " (image totals " << num(ps::testrender::total(drt.mean)) << " and "
                                << num(ps::testrender::total(pt.mean)) << "):\n  " << z.report << "\n  " << hint);
}

}  // namespace

TEST_CASE(
    "drt: equals pt where every path is one of DRT's, L D? (G|S)* E: soft shadow, glossy and mirror (z-test) [2 pts]") {
    // Two comparisons, each at sidak(alpha(), 2): the table, and a glossy floor under a lamp.
    const double level = ps::stats::sidak(alpha(), 2);
    const ps::testrender::Render drt = renderAt(kTable, "drt", -1, 512, 1111);
    const ps::testrender::Render pt = renderAt(kTable, "pt", -1, 2048, 1112);
    CHECK_MESSAGE(drt.stats.bad() == 0, "drt: expected 0 NaN and 0 Inf samples, got " << drt.stats.nan << " NaN and "
                                                                                      << drt.stats.inf << " Inf");
    // Both images black would pass the z-test: the lamp lights the table, so drt must not be.
    REQUIRE_MESSAGE(ps::testrender::total(drt.mean) > 0.0,
                    "drt renders the table under its lamp black: LiDistributed returns nothing yet");
    const ps::stats::ZTestResult z = ps::stats::zTestImages(drt.mean, drt.variance, pt.mean, pt.variance, level);
    CHECK_MESSAGE(
        z.passed,
        "drt (a) against pt (b) on the table between a glossy and a mirror sphere (maxdepth 2; image totals "
            << num(ps::testrender::total(drt.mean)) << " and " << num(ps::testrender::total(pt.mean)) << "):\n  "
            << z.report
            << "\n  Every path here is L D? (G|S)* E. A light sample is f Le |cos| / pdf (sampleDirectLight's "
               "value), weight 1 at a diffuse point and the power heuristic at a glossy one; the glossy "
               "ray's emission the power heuristic too, full after a mirror; the glossy sample's weight is "
               "b.weight = f |cos| / pdf, not the lobe's pdf alone");
    checkDrtAgainstPt(kGlossyFloor, -1, 512, 1024, 1115, level,
                      "on a glossy floor (Phong, exponent 8) under a lamp, every path L G E",
                      "The light sample and the glossy ray that hits the lamp sample the same paths: each weighted "
                      "by the power heuristic against the other (the ray's emission in full only after a delta "
                      "bounce or from the camera)");
}

TEST_CASE(
    "drt: no diffuse interreflection: in a closed diffuse box it equals direct light, pt with maxdepth 1 (z-test) [1 pt]") {
    // Two comparisons, each at sidak(alpha(), 2): the box, and a mirror over a floor at maxdepth 1.
    const double level = ps::stats::sidak(alpha(), 2);
    checkDrtAgainstPt(kClosedBox, 1, 256, 1024, 1113, level, "with maxdepth 5 and 1 in a closed box of albedo 0.7",
                      "A diffuse point ends the path: its light sample (weight 1) is all it adds",
                      "drt renders the lit box black: LiDistributed returns nothing yet");
    checkDrtAgainstPt(kMirrorOverFloor, -1, 256, 1024, 1117, level,
                      "both with maxdepth 1, on a floor seen in a mirror sphere",
                      "A diffuse point reached with the scene's maxdepth bounces takes no light sample: that path "
                      "would have one bounce too many");
}

TEST_CASE(
    "drt: equals pt filtered to L D? (G|S)* E on the Cornell box through a lens, where pt carries more paths "
    "(z-test against the stored reference) [2 pts]") {
    // scenes/cornell-lens.scene at 24 x 24 (maxdepth 8, a lens of radius 40 mm focused on the
    // glossy sphere, which stands under the lamp; a mirror and a diffuse sphere behind it). Here
    // the full transport holds what drt must leave out: L D D+ E (the walls' light on each other),
    // L G D E and L S D E (the spheres' caustics). The reference is pt restricted to Eq. 11.19's
    // paths by Heckbert's expression, tests/11-classics/data/cornell-lens-24-drt.pfm and its
    // variance (262144 spp). drt at 1024 spp, per-pixel z-test at alpha() (lens_support.h): each
    // of the 1728 pixel channels at the Sidak level over the channels, 99.75 % must pass; drt's
    // variance at least the reference's per sample (judgedVariance).
    const ps::Scene scene = loadSceneAt("scenes/cornell-lens.scene", 24, 24);
    REQUIRE(scene.settings.maxDepth == 8);
    REQUIRE_MESSAGE((ps::thinLens(scene.camera) && ps::thinLens(scene.camera)->radius() == 40.0f),
                    "scenes/cornell-lens.scene's lens is no longer 40 mm: "
                    "the stored reference is out of date");
    const ps::Image ref = ps::readPFM(sourcePath("tests/11-classics/data/cornell-lens-24-drt.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/11-classics/data/cornell-lens-24-drt-variance.pfm"));
    constexpr int kSpp = 1024, kRefSpp = 262144;
    const ps::testrender::Render drt = ps::testrender::render(scene, "drt", kSpp, ps::testseed::seed(1117));
    CHECK_MESSAGE(drt.stats.bad() == 0, "drt: expected 0 NaN and 0 Inf samples, got " << drt.stats.nan << " NaN and "
                                                                                      << drt.stats.inf << " Inf");
    REQUIRE_MESSAGE(ps::testrender::total(drt.mean) > 0.0,
                    "drt renders the Cornell box black: LiDistributed returns nothing yet");
    const double total = ps::testrender::total(drt.mean), refTotal = ps::testrender::total(ref);
    const ps::stats::ZTestResult z =
        ps::stats::zTestImages(drt.mean, judgedVariance(drt.variance, kSpp, refVar, kRefSpp), ref, refVar, alpha());
    CHECK_MESSAGE(z.passed,
                  "drt (a, 1024 spp) against pt --paths '"
                      << ps::kDistributedPaths << "' (b, the stored reference) on the Cornell box through the lens:\n  "
                      << z.report << "\n  image sums: drt " << num(total) << ", reference " << num(refTotal)
                      << " (ratio " << num(total / refTotal)
                      << "). Brighter walls: a diffuse point must end the path, its light sample is all it adds "
                         "(no L D D ... E); the glossy sphere wrong: its light sample and its glossy ray's "
                         "emission are MIS-weighted (power heuristic) against each other, and the glossy ray "
                         "carries b.weight = f |cos| / pdf");
}
