// Stiff and extreme cases (../shared/notes/testing.md, "Stiff and extreme cases"), run through
// every registered integrator: the framework's first-hit views and every lesson's estimators,
// including those added later. What each must do: never a NaN or Inf sample, never a crash or a
// hang, and the exact answer where one is known without statistics (a black image). With an
// untouched assignment an estimator returns black, which passes most of these: they are
// framework tests (ungraded), guarding the reference and the framework it calls.
#include <doctest/doctest.h>
#include <cmath>
#include <map>
#include <string>
#include <vector>
#include "11-classics/path_filter.h"
#include "errors.h"
#include "format.h"
#include "statistics.h"
#include "integrator.h"
#include "render.h"
#include "scene_loader.h"
#include "scene_text.h"
#include "seed.h"

using namespace ps;

namespace {

// The integrators that estimate light transport: every registered one except the first-hit
// views, which show reflectance or normals and need no light.
std::vector<std::string> transportAlgorithms() {
    std::vector<std::string> names;
    for (const IntegratorInfo& i : integratorList())
        if (i.name != "eyelight" && i.name != "normals") names.push_back(i.name);
    return names;
}
std::vector<std::string> allAlgorithms() {
    std::vector<std::string> names;
    for (const IntegratorInfo& i : integratorList()) names.push_back(i.name);
    return names;
}

// Whether the integrator refuses the scene outright (IntegratorCaps::checkScene: lesson 11's
// radiosity renders diffuse quads lit by quads only). Such pairs are left out here; the refusal
// itself is tested with the integrator (tests/framework/cli).
bool refuses(const std::string& algo, const Scene& scene) {
    const std::unique_ptr<Integrator> i = makeIntegrator(algo);
    try {
        if (i->caps.checkScene) i->caps.checkScene(scene);
    } catch (const InputError&) { return true; }
    return false;
}

struct Result {
    Image mean;
    SampleStats stats;
};

// algo may be "pt --paths EXPR": pt's filtered form (lesson 11), the reference of an integrator that
// carries only some paths (lesson 11's carriedPaths).
Result renderWith(const Scene& scene, const std::string& algo, int spp, uint64_t seed = 7) {
    const std::string flag = " --paths ";
    const size_t at = algo.find(flag);
    std::unique_ptr<Integrator> integrator;
    if (at == std::string::npos) {
        integrator = makeIntegrator(algo);
    } else {
        integrator = makeIntegrator(algo.substr(0, at), {{"paths", algo.substr(at + flag.size())}});
    }
    RenderOptions opt;
    opt.spp = spp;
    opt.seed = seed;
    const RenderResult r = render(scene, *integrator, opt);
    return {r.film.mean(), r.stats};
}

// The first pixel that is not exactly black, as "(x, y) = (r, g, b)", or "" if none.
std::string firstNonBlack(const Image& img) {
    for (int i = 0; i < img.width * img.height; ++i) {
        const Color& c = img.pixels[i];
        if (c.r != 0.0f || c.g != 0.0f || c.b != 0.0f)
            return "(" + std::to_string(i % img.width) + ", " + std::to_string(i / img.width) +
                   ") = " + fmt::str(Vec3(c.r, c.g, c.b));
    }
    return "";
}

double meanValue(const Image& img) {
    double s = 0.0;
    for (const Color& c : img.pixels) s += double(c.r) + c.g + c.b;
    return s / (3.0 * img.pixels.size());
}

// Renders `text` with every algorithm in `algos`: no NaN or Inf sample, and (if black) an
// exactly black image.
void checkAll(const std::string& what, const std::string& text, const std::vector<std::string>& algos, int spp,
              bool black) {
    const Scene scene = parseScene(text, what + ".scene");
    for (const std::string& algo : algos) {
        CAPTURE(algo);
        if (refuses(algo, scene)) continue;
        const Result r = renderWith(scene, algo, spp);
        CHECK_MESSAGE(r.stats.nan == 0, what << ", " << algo << ": " << r.stats.nan << " NaN samples");
        CHECK_MESSAGE(r.stats.inf == 0, what << ", " << algo << ": " << r.stats.inf << " Inf samples");
        if (black) {
            const std::string where = firstNonBlack(r.mean);
            CHECK_MESSAGE(where.empty(), what << ", " << algo << ": expected a black image, got pixel " << where);
        }
    }
}

const char* kCamera = "camera eye 0 1 -4  target 0 0.5 0  fov 45  resolution 16 16\n";

}  // namespace

TEST_CASE("extreme: the integrators are all here (the lessons' integrators are linked in)") {
    // Guards the tests below: they would pass vacuously if only the framework's views ran.
    const std::vector<std::string> names = transportAlgorithms();
    std::string list;
    for (const std::string& n : names) list += n + " ";
    CHECK_MESSAGE(names.size() >= 3,
                  "expected the lessons' integrators (pt, ...) besides eyelight and normals, got: " << list);
}

TEST_CASE("extreme: an empty scene (a camera and nothing else) is black for every integrator") {
    checkAll("empty", kCamera, allAlgorithms(), 2, true);
}

TEST_CASE("extreme: a closed box without lights is black for every light transport integrator") {
    const std::string text = std::string(kCamera) +
                             "material w diffuse albedo 0.9 0.9 0.9\n"
                             "material g phong albedo 0.9 0.9 0.9 exponent 100\n"
                             "quad -2 0 -5  2 0 -5  2 0 2  -2 0 2  material w\n"    // floor
                             "quad -2 3 -5  -2 3 2  2 3 2  2 3 -5  material w\n"    // ceiling
                             "quad -2 0 2  2 0 2  2 3 2  -2 3 2  material g\n"      // back
                             "quad -2 0 -5  -2 3 -5  2 3 -5  2 0 -5  material w\n"  // front, behind the camera
                             "quad -2 0 -5  -2 0 2  -2 3 2  -2 3 -5  material w\n"  // left
                             "quad 2 0 -5  2 3 -5  2 3 2  2 0 2  material w\n"      // right
                             "sphere center 0 0.5 0  radius 0.5  material g\n";
    checkAll("no-lights", text, transportAlgorithms(), 2, true);
}

TEST_CASE("extreme: a point light seen only in a mirror and through glass by the pinhole gives 0") {
    // Every light path is L S* E with a delta light, specular surfaces only and a pinhole: no
    // unbiased technique can sample it (no hit on the point light, no connection through a delta
    // BSDF or to the pinhole), so the exact answer of every technique is 0 — never a NaN from
    // "0 / 0" pdfs of delta events.
    const std::string text = std::string(kCamera) +
                             "material m mirror\n"
                             "material glass dielectric ior 1.5\n"
                             "quad -3 0 -5  -3 0 3  3 0 3  3 0 -5  material m\n"
                             "sphere center 0 0.7 0  radius 0.6  material glass\n"
                             "sphere center 1.2 0.4 0.5  radius 0.3  material m\n"
                             "pointlight position 0 2.5 0.5  intensity 10 10 10\n";
    checkAll("point-light-specular", text, transportAlgorithms(), 4, true);
}

TEST_CASE("extreme: point lights on a surface, at a corner and on an edge give finite images") {
    const std::string text = std::string(kCamera) +
                             "material w diffuse albedo 0.8 0.8 0.8\n"
                             "material g phong albedo 0.8 0.8 0.8 exponent 20\n"
                             "quad -1 0 -1  -1 0 1  1 0 1  1 0 -1  material w\n"
                             "quad -1 0 1  1 0 1  1 2 1  -1 2 1  material g\n"
                             "pointlight position 0.3 0 0.2  intensity 1 1 1\n"  // on the floor
                             "pointlight position -1 0 1  intensity 1 1 1\n"     // at a corner of both quads
                             "pointlight position 0.5 0 1  intensity 1 1 1\n"    // on the shared edge
                             "pointlight position 0 1 1  intensity 1 1 1\n";     // on the back wall
    checkAll("point-light-on-surface", text, transportAlgorithms(), 4, false);
}

TEST_CASE("extreme: tiny bright lights (sphere r = 1e-4, triangle 1e-5 wide, L r^2 constant) give finite images") {
    const std::string text = std::string(kCamera) +
                             "material w diffuse albedo 0.8 0.8 0.8\n"
                             "material g phong albedo 0.8 0.8 0.8 exponent 10000\n"
                             "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material g\n"
                             "quad -2 0 2  2 0 2  2 2 2  -2 2 2  material w\n"
                             "sphere center -0.5 1 0  radius 1e-4  emission 1e8 1e8 1e8\n"
                             "triangle 0.5 1.5 0  0.50001 1.5 0  0.5 1.5 0.00001  emission 1e10 1e10 1e10\n";
    checkAll("tiny-lights", text, transportAlgorithms(), 4, false);
}

TEST_CASE(
    "extreme: Phong exponents 0, 1e4, 1e6 and 1e7 (the loader's largest) next to a mirror and glass give finite images") {
    const std::string text = std::string(kCamera) +
                             "material p0 phong albedo 0.8 0.8 0.8 exponent 0\n"
                             "material p4 phong albedo 0.8 0.8 0.8 exponent 10000\n"
                             "material p6 phong albedo 0.8 0.8 0.8 exponent 1000000\n"
                             "material p7 phong albedo 0.8 0.8 0.8 exponent 1e7\n"
                             "material m mirror\n"
                             "material glass dielectric ior 1.5\n"
                             "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material p6\n"
                             "quad -2 0 2  2 0 2  2 2 2  -2 2 2  material p4\n"
                             "quad -2 0 -2  -2 2 -2  -2 2 2  -2 0 2  material p0\n"
                             "sphere center 0.6 0.4 0  radius 0.4  material glass\n"
                             "sphere center -0.6 0.4 0.5  radius 0.4  material m\n"
                             "sphere center 0 1.2 1  radius 0.3  material p7\n"
                             "quad -0.3 2 -0.3  0.3 2 -0.3  0.3 2 0.3  -0.3 2 0.3  emission 5 5 5\n"
                             "pointlight position 1 1.5 -1  intensity 1 1 1\n"
                             "background radiance 0.2 0.2 0.2\n";
    checkAll("phong-extremes", text, transportAlgorithms(), 4, false);
}

TEST_CASE(
    "extreme: grazing rays (camera in the plane of a wall, lights in the plane of the floor) give finite images") {
    const std::string text =
        "camera eye 0 0 -4  target 0 0 0  fov 45  resolution 16 16\n"  // in the floor's plane y = 0
        "material w diffuse albedo 0.8 0.8 0.8\n"
        "material g phong albedo 0.8 0.8 0.8 exponent 50\n"
        "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material g\n"
        "quad 0 -1 -2  0 -1 2  0 1 2  0 1 -2  material w\n"    // a wall seen edge-on
        "quad -2 0 3  2 0 3  2 2 3  -2 2 3  emission 1 1 1\n"  // its lower edge on the floor's plane
        "pointlight position 1 0 1  intensity 1 1 1\n";        // in the floor's plane
    checkAll("grazing", text, transportAlgorithms(), 4, false);
}

TEST_CASE("extreme: albedo 1 in a closed emitting box terminates at the maximum depth, finite") {
    // Russian roulette never kills a throughput-1 path before its survival probability drops, so
    // only the maximum depth ends it: the render must finish (ctest's timeout guards a hang).
    std::string text = scenetext::readText(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/furnace.scene");
    const size_t at = text.find("albedo 0.5 0.5 0.5");
    REQUIRE_MESSAGE(at != std::string::npos, "scenes/furnace.scene no longer says 'albedo 0.5 0.5 0.5'");
    text.replace(at, 18, "albedo 1 1 1");
    text = scenetext::transformScene(text, 1.0, 0.0, 8);
    Scene scene = parseScene(text, "furnace-albedo-1.scene");
    scene.settings.maxDepth = 40;
    for (const std::string& algo : transportAlgorithms()) {
        CAPTURE(algo);
        const Result r = renderWith(scene, algo, 2);
        CHECK_MESSAGE(r.stats.bad() == 0, algo << ": " << r.stats.nan << " NaN and " << r.stats.inf << " Inf samples");
        CHECK_MESSAGE(meanValue(r.mean) <= 41.0 * 1.5,
                      algo << ": mean " << meanValue(r.mean)
                           << " is far above (D + 1) Le = 41: paths longer than the maximum depth?");
    }
}

TEST_CASE("extreme: the Cornell spheres scaled by 1e-4 and 1e4 and moved by 1e5 give the same image") {
    // Same seed, same random numbers: the paths are the same up to float rounding of the
    // geometry, so the images agree closely; an absolute epsilon anywhere (acne, leaks, lost
    // shadow rays) changes them by far more. Bound: the mean over the image within 1 % (measured
    // with the reference solutions: at most 0.1 %). The point-light box too, its intensity
    // scaled by s^2.
    const std::string dir = std::string(PATHSPACE_SOURCE_DIR) + "/scenes/";
    for (const char* file : {"cornell-spheres.scene", "cornell-point-light.scene"}) {
        const std::string text = scenetext::readText(dir + file);
        const Scene base = parseScene(scenetext::transformScene(text, 1.0, 0.0, 24), file);
        struct Case {
            double s, t;
            const char* name;
        };
        for (const std::string& algo : transportAlgorithms()) {
            if (refuses(algo, base)) continue;
            const Result ref = renderWith(base, algo, 4);
            REQUIRE(ref.stats.bad() == 0);
            const double m0 = meanValue(ref.mean);
            for (const Case c :
                 {Case{1e-4, 0.0, "scaled by 1e-4"}, Case{1e4, 0.0, "scaled by 1e4"}, Case{1.0, 1e5, "moved by 1e5"}}) {
                const Scene scene = parseScene(scenetext::transformScene(text, c.s, c.t, 24), file);
                const Result r = renderWith(scene, algo, 4);
                CHECK_MESSAGE(r.stats.bad() == 0,
                              file << " " << c.name << ", " << algo << ": " << r.stats.bad() << " NaN/Inf samples");
                const double m = meanValue(r.mean);
                // Lesson 6's per-technique integrators (path-s0 ...) render paths of exactly
                // maxdepth + 1 = 9 edges only: moved by 1e5, the rounding of the coordinates
                // (8e-3 instead of 3e-5) makes such long paths diverge from the original ones
                // within 9 bounces, so the same seed no longer gives the same paths. They are
                // compared statistically against their own original image instead (next test).
                // Likewise Metropolis (mmlt: one acceptance decided otherwise and the chain goes
                // elsewhere) and splitting (pt-adrrs: the cache's cells and the branching follow the
                // rounded points): moved by 1e5 they are two independent estimates, 1-3 % apart at 4
                // spp (measured once the random numbers were drawn in a fixed order); only their NaN/Inf
                // count is checked here. So for guiding (pt-guided, pt-guided-adrrs: the learned
                // field's cells and the directions sampled from it follow the rounded points; 3 and
                // 4 % apart on the point light at 4 spp, measured).
                if (c.t != 0.0 && (algo.rfind("path-", 0) == 0 || algo == "mmlt" || algo == "pt-adrrs" ||
                                   algo.rfind("pt-guided", 0) == 0))
                    continue;
                CHECK_MESSAGE(std::abs(m - m0) <= 0.01 * m0 + 1e-12,
                              file << " " << c.name << ", " << algo << ": image mean " << m << ", original " << m0);
            }
        }
    }
}

TEST_CASE(
    "extreme: lesson 6's single-technique integrators moved by 1e5 agree with themselves at the origin (t-test)") {
    // The moved-by-1e5 comparison above needs the same paths for the same seed; the path-*
    // integrators' 9-edge paths decorrelate under the coarse rounding of the moved scene, so here
    // each one is compared with its own image at the original position as two independent
    // estimates of the same number: the image mean, from kRuns independent renders (seeds apart)
    // per position. Welch's t-test, two-sided, alpha = 0.01 with Sidak over every comparison;
    // power: the standard error of the difference must be below 20 % of the mean, or the test
    // could not see a leak or a lost shadow ray (those change the mean by far more).
    const std::string dir = std::string(PATHSPACE_SOURCE_DIR) + "/scenes/";
    std::vector<std::string> algos;
    for (const std::string& a : transportAlgorithms())
        if (a.rfind("path-", 0) == 0) algos.push_back(a);
    REQUIRE_MESSAGE(!algos.empty(), "lesson 6's path-* integrators are not registered");
    const char* files[] = {"cornell-spheres.scene", "cornell-point-light.scene"};
    const int comparisons = int(algos.size()) * 2;
    const double alpha = stats::sidak(0.01, comparisons);
    constexpr int kRuns = 24, kSpp = 32, kRes = 16;
    for (const char* file : files) {
        const std::string text = scenetext::readText(dir + file);
        const Scene original = parseScene(scenetext::transformScene(text, 1.0, 0.0, kRes), file);
        const Scene moved = parseScene(scenetext::transformScene(text, 1.0, 1e5, kRes), file);
        for (const std::string& algo : algos) {
            stats::Welford a, b;
            uint64_t bad = 0;
            for (int i = 0; i < kRuns; ++i) {
                const Result ra = renderWith(original, algo, kSpp, 1000 + uint64_t(i));
                const Result rb = renderWith(moved, algo, kSpp, 5000 + uint64_t(i));
                bad += ra.stats.bad() + rb.stats.bad();
                a.add(meanValue(ra.mean));
                b.add(meanValue(rb.mean));
            }
            CHECK_MESSAGE(bad == 0, file << " moved by 1e5, " << algo << ": " << bad << " NaN/Inf samples");
            const double se = std::sqrt(a.variance() / a.n + b.variance() / b.n);
            const double diff = b.mean - a.mean;
            const double t = se > 0.0 ? std::abs(diff) / se : (diff == 0.0 ? 0.0 : INFINITY);
            const double dof = double(2 * kRuns - 2);
            const double p = stats::studentTwoSided(t, dof);
            MESSAGE(file << ", " << algo << ": original " << a.mean << ", moved by 1e5 " << b.mean << ", se " << se
                         << ", t = " << t << ", p = " << p);
            CHECK_MESSAGE(p >= alpha, file << " moved by 1e5, " << algo << ": image mean " << b.mean << " against "
                                           << a.mean << " at the origin (difference " << diff << ", standard error "
                                           << se << ", p = " << p << " < alpha " << alpha
                                           << "): light leaks or lost shadow rays in the moved scene?");
            CHECK_MESSAGE(se <= 0.2 * std::abs(a.mean), file << ", " << algo << ": standard error " << se
                                                             << " of the difference is above 20 % of the mean "
                                                             << a.mean << ": the test has no power");
        }
    }
}

namespace {

// The image mean without the 3 x 3 pixels around raster position `around` (none if it is off
// the image).
double meanWithout(const Image& img, bool off, const Vec2& around) {
    const int cx = int(std::floor(around.x)), cy = int(std::floor(around.y));
    double s = 0.0;
    size_t n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            if (!off && std::abs(x - cx) <= 1 && std::abs(y - cy) <= 1) continue;
            const Color& c = img.pixels[size_t(y) * img.width + x];
            s += double(c.r) + c.g + c.b;
            n += 3;
        }
    return s / double(n);
}

}  // namespace

namespace {
// scenes/cornell-point-light.scene with its point light moved onto surfaces of the box.
struct SurfaceLightCase {
    std::string where;     // "on the ceiling", for messages
    std::string position;  // the light's, in the scene's millimetres
    std::string warning;   // what the loader's warning says
    int spp;               // per render
    double power;          // the standard error of a difference must be below this fraction of
    double pathPower;      // the reference's mean (pathPower for lesson 6's path-*)
};

// Every registered integrator renders the case; each one that estimates light transport is
// compared with its reference, as two independent estimates of the same number: the image mean
// without the 3 x 3 pixels around the light (lt and bpt see the point light itself there, the
// path L E, which pt cannot sample), from kRuns renders each (4 kRuns for the spikier single
// techniques path-*), every render with its own seed (mix64 of the base and its number: seeds
// base + 7919 i, used before, gave runs whose means agreed more closely than independent runs
// do, so a standard error too small). References: pt for the full transport; lesson 6's path-s1
// for its fixed-length single-technique integrators (path-*); direct-light for lesson 2's
// direct-* integrators; pt filtered to the expression of an integrator that carries only some
// paths (lesson 11's classics, lesson 11's carriedPaths: whitted's L[DG]S*E|LS*E, drt's
// LD?(G|S)*E, which in this all-diffuse box is direct light). BSDF sampling alone never hits a
// point light: pt-bsdf, direct-bsdf and path-s0 must be exactly black. Welch's t-test,
// two-sided, alpha = 0.01 with Sidak over every comparison; power: the standard error of the
// difference below c.power (c.pathPower for path-*) of the reference mean, the largest measured
// over PATHSPACE_TEST_SEED = 0 .. 7 with a margin (the cases say which).
void checkSurfacePointLight(const SurfaceLightCase& c) {
    std::string text = scenetext::readText(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/cornell-point-light.scene");
    const std::string before = "pointlight position 278 538.8 279.5";
    const size_t at = text.find(before);
    REQUIRE_MESSAGE(at != std::string::npos, "scenes/cornell-point-light.scene no longer says '" << before << "'");
    text.replace(at, before.size(), "pointlight position " + c.position);
    constexpr int kRes = 16, kRuns = 16;
    const std::string& where = c.where;
    const Scene scene =
        parseScene(scenetext::transformScene(text, 1.0, 0.0, kRes), "cornell-point-light " + where + ".scene");
    // Lesson 6's path-* render paths of exactly maxdepth + 1 edges: 4 here (the scene's 9-edge
    // paths are too faint and noisy for the test's power), so that every technique s = 1 .. 4
    // (s = 4 is t = 1, light tracing) has a light vertex y_1 (where the stray hits were) or a
    // shadow ray to the light.
    Scene shortPaths = scene;
    shortPaths.settings.maxDepth = 3;
    bool warned = false;
    for (const std::string& w : scene.warnings) warned = warned || w.find(c.warning) != std::string::npos;
    CHECK_MESSAGE(warned, "no warning that the point light " << c.warning);
    Vec2 lightRaster;
    const bool off = !scene.camera.rasterPosition(scene.lights[0].position, lightRaster);

    // What an integrator carries (lesson 11's carriedPaths): every path, or the paths of an
    // expression (lesson 11's classics: pt filtered to it is the reference), or "" when no
    // expression says which (then only finite and not black, as the biased ones).
    const auto carried = [&](const std::string& algo) { return carriedPaths(algo, scene); };
    const auto reference = [&](const std::string& algo) -> std::string {
        if (algo.rfind("path-", 0) == 0) return "path-s1";
        if (algo.rfind("direct-", 0) == 0) return "direct-light";
        const std::string paths = carried(algo);
        if (paths != kAllPaths && !paths.empty()) return "pt --paths " + paths;
        return "pt";
    };
    const auto black = [](const std::string& algo) {
        return algo == "pt-bsdf" || algo == "direct-bsdf" || algo == "path-s0";
    };
    // Photon mapping (lesson 8) is consistent, not unbiased: its expectation differs from pt's by
    // the density estimate's blur (lesson 8, Eq. 8.12), so it is not t-tested here, only checked
    // for a finite, non-black image (lesson 8's graded tests bound the bias of pm, pm-ic and ppm
    // on the Cornell box).
    // So is every form of lesson 13's vcm that merges (vcm, vcm-balance, vcm-bpm, vcm-ppm): a merge
    // blurs over its radius, and in the corner, next to the point light, the blur is what the
    // t-test sees (lesson 13's consistency test bounds it); vcm-bpt (no merges) is t-tested.
    const auto merges = [](const std::string& algo) { return algo.rfind("vcm", 0) == 0 && algo != "vcm-bpt"; };
    // Lesson 6's path-s2 and path-s3 connect two surface vertices, y_{s-1} and z, through
    // G = cos cos / d^2, which is unbounded where two walls meet: their variance is infinite. Over
    // PATHSPACE_TEST_SEED = 0 .. 29 (64 renders each) their means on the ceiling fell 5-7 % below
    // path-s1's at p < 2e-4 for some seeds (no rare large sample among the 64) and not for
    // others: a t-test on them has no valid standard error, so they are checked as the biased
    // ones are (lesson 6's graded tests check each technique's pdfs exactly). path-s4 = path-t1
    // (light tracing) and path-s1 (next-event estimation) connect to the camera or the light,
    // where G is bounded here, and are t-tested.
    const auto infiniteVariance = [](const std::string& algo) { return algo == "path-s2" || algo == "path-s3"; };
    const auto biased = [&](const std::string& algo) {
        return algo == "pm" || algo == "pm-ic" || algo == "ppm" || merges(algo) || carried(algo).empty() ||
               infiniteVariance(algo);
    };
    struct Estimate {
        stats::Welford w;
        uint64_t bad = 0;
        std::string nonBlack;
    };
    const auto isPath = [](const std::string& algo) { return algo.rfind("path-", 0) == 0; };
    const auto runs = [&](const std::string& algo) { return isPath(algo) ? 4 * kRuns : kRuns; };
    const auto estimate = [&](const std::string& algo, uint64_t seed) {
        Estimate e;
        for (int i = 0; i < runs(algo); ++i) {
            const Result r = renderWith(isPath(algo) ? shortPaths : scene, algo, c.spp, mix64(seed + uint64_t(i)));
            e.bad += r.stats.bad();
            e.w.add(meanWithout(r.mean, off, lightRaster));
            if (e.nonBlack.empty()) e.nonBlack = firstNonBlack(r.mean);
        }
        return e;
    };
    std::vector<std::string> compared;
    for (const std::string& algo : transportAlgorithms())
        if (!black(algo) && !biased(algo) && algo != reference(algo) && !refuses(algo, scene)) compared.push_back(algo);
    const double alpha = stats::sidak(0.01, int(compared.size()));
    std::map<std::string, Estimate> refs;
    for (const std::string& algo : allAlgorithms()) {
        CAPTURE(algo);
        if (refuses(algo, scene)) continue;
        const bool transport = algo != "eyelight" && algo != "normals";
        if (!transport || black(algo)) {
            const Result r = renderWith(scene, algo, 2);
            CHECK_MESSAGE(r.stats.bad() == 0, algo << ": " << r.stats.bad() << " NaN/Inf samples");
            if (transport) {
                const std::string where = firstNonBlack(r.mean);
                CHECK_MESSAGE(where.empty(),
                              algo << " cannot reach a point light, expected a black image, got pixel " << where);
            }
            continue;
        }
        if (biased(algo)) {
            const Result r = renderWith(scene, algo, 2);
            CHECK_MESSAGE(r.stats.bad() == 0, algo << ": " << r.stats.bad() << " NaN/Inf samples");
            CHECK_MESSAGE(!firstNonBlack(r.mean).empty(), algo << ": a black image");
            continue;
        }
        const std::string refName = reference(algo);
        if (!refs.count(refName)) refs[refName] = estimate(refName, testseed::seed(100));
        const Estimate& ref = refs[refName];
        REQUIRE_MESSAGE(ref.bad == 0, refName << ": " << ref.bad << " NaN/Inf samples");
        REQUIRE_MESSAGE(ref.w.mean > 0.0, refName << " (the reference) renders black");
        if (algo == refName) continue;
        const Estimate e = estimate(algo, testseed::seed(1000003));  // seeds apart from the reference's
        CHECK_MESSAGE(e.bad == 0, where << ", " << algo << ": " << e.bad << " NaN/Inf samples");
        struct Comparison {
            double diff, se, t, p;
        };
        const auto compare = [&](const Estimate& x, const Estimate& r) {
            Comparison k;
            k.se = std::sqrt(x.w.variance() / double(x.w.n) + r.w.variance() / double(r.w.n));
            k.diff = x.w.mean - r.w.mean;
            k.t = k.se > 0.0 ? std::abs(k.diff) / k.se : (k.diff == 0.0 ? 0.0 : INFINITY);
            k.p = stats::studentTwoSided(k.t, double(x.w.n + r.w.n - 2));
            return k;
        };
        const Comparison k = compare(e, ref);
        const double se = k.se;
        MESSAGE(algo << " against " << refName << ": " << e.w.mean << " vs " << ref.w.mean << " ("
                     << 100.0 * k.diff / ref.w.mean << " %), se " << k.se << ", t = " << k.t << ", p = " << k.p);
        // A difference is reported when a second comparison, of new renders of both with other
        // seeds, finds it too (level alpha^2 <= alpha): the run means have heavier tails than a
        // normal's (close connections where the box's walls meet), and single comparisons fell
        // below alpha in 2 of 60 runs of these tests over PATHSPACE_TEST_SEED = 0 .. 29, where
        // bpt and pt agree in the corner within 0.13 +- 0.12 % (64 x 256 spp each). The errors of
        // issue 31 were 4 to 60 %, far beyond both.
        Comparison k2 = k;
        Estimate e2, ref2;
        if (k.p < alpha) {
            e2 = estimate(algo, testseed::seed(2000003));
            ref2 = estimate(refName, testseed::seed(3000017));
            k2 = compare(e2, ref2);
            MESSAGE(algo << " against " << refName << " again: " << e2.w.mean << " vs " << ref2.w.mean << " ("
                         << 100.0 * k2.diff / ref2.w.mean << " %), t = " << k2.t << ", p = " << k2.p);
        }
        CHECK_MESSAGE((k.p >= alpha || k2.p >= alpha),
                      algo << ": image mean " << e.w.mean << " against " << refName << "'s " << ref.w.mean << " ("
                           << 100.0 * k.diff / ref.w.mean << " %, standard error " << k.se << ", p = " << k.p
                           << "), and again " << 100.0 * k2.diff / ref2.w.mean << " % (p = " << k2.p
                           << "), both < alpha " << alpha << ": rays from the light " << where
                           << " hit a surface it lies on, or shadow rays to it do?");
        const double power = isPath(algo) ? c.pathPower : c.power;
        CHECK_MESSAGE(se <= power * ref.w.mean, algo << ": standard error " << se << " of the difference is above "
                                                     << 100.0 * power << " % of " << refName << "'s mean " << ref.w.mean
                                                     << ": the test has no power");
    }
}
}  // namespace

TEST_CASE(
    "extreme: a point light exactly on the Cornell box's ceiling: every integrator agrees with its reference (t-test)") {
    // The light moved up 10 mm onto the ceiling's plane y = 548.8. What is physically right: the
    // light is a point in the plane of the one-sided ceiling, so the ceiling gets none of its
    // light (cos = 0 there), the half of its light going up leaves through the ceiling's back,
    // and the lower half lights the box. The framework takes a point light on a surface to be so
    // (Scene::findSurfacePointLights, with a warning): rays from it and shadow rays to it are
    // offset off the surface to their own side. Without that, rays leaving the light hit the
    // ceiling at t = +-ulps in a third of all directions (the watertight test's rounding),
    // scattering light at the light's position that pt never sees: lt was 5.5 % dark and bpt
    // 14.7 % bright against pt.
    // Without the fix, at this size: lt -9 %, bpt +10 %, bpt-balance +8 %, bpt-full -13 % against
    // pt, path-s2 .. path-s4 and path-t1 -27 .. -29 % against path-s1, every one at p < 1e-13.
    checkSurfacePointLight({"on the ceiling", "278 548.8 279.5", "lies on a surface", 32, 0.04, 0.04});
}

TEST_CASE(
    "extreme: a point light exactly in a corner of the Cornell box (ceiling, back and side wall): every integrator "
    "agrees with its reference (t-test)") {
    // The light at (0, 548.8, 559.2), where the ceiling, the back wall and the green wall meet.
    // What is physically right: it is a point in all three planes, so none of the three gets its
    // light, the eighth of it that goes into the box lights the box, and the rest leaves behind
    // the walls. The framework takes it so (Light::surfacePlanes): a ray from it, or a shadow
    // ray to it, starts off each of the three planes on the side it goes to (lightRayPoint).
    // Issue 31: it was offset along the three walls' mean normal only, which puts the rays of
    // half the directions inside the box although 5/8 of them (those with a positive component
    // along the mean normal but outside the box's octant) leave through a wall's plane: they hit
    // the walls at the light and scattered light pt never sees. lt and bpt were 1.5 to 2 times
    // pt's image, bpt-full 4-6 % above it, path-s2..s4 and path-t1 likewise above path-s1.
    // Without the fix, at this size: lt +60 %, bpt +58 %, bpt-balance +58 %, mmlt +51 %, bpt-full
    // +4.2 % (t = 8.5) against pt; path-s3 +14 %, path-s4 and path-t1 +5.9 % against path-s1.
    // 7/8 of the light leaves the box: light paths mostly miss it, so twice the ceiling's spp.
    checkSurfacePointLight({"in a corner", "0 548.8 559.2", "lies on 3 surfaces at an edge or corner", 64, 0.04, 0.04});
}

TEST_CASE("extreme: albedo 1 in a closed emitting box at maximum depth 1e5: no path ends early (pt-bsdf, exact)") {
    // The closed furnace (scenes/furnace.scene) with albedo 1: every path's throughput stays
    // exactly 1 and gathers Le = 1 at each of its D + 1 vertices, so each pt-bsdf sample is
    // exactly D + 1 (sums of integers below 2^24, exact in float) unless its path ends before the
    // maximum depth, and the image must be D + 1 in every pixel, exactly: no statistics. Two
    // causes once ended 1.1e-7 of the bounces (44 of 4096 paths of 10^5 bounces; at 4 x 4 and
    // 16 spp pt-bsdf was 0.66 %, pt 0.33 %, lt 0.41 % low): the cosine warp sent u with a
    // coordinate 0 to the disk's rim (pdf 0: sample lost; fixed by cosineWarpU, framework
    // sampling.h), and a ray leaving a hit on the edge where two walls meet started on the other
    // wall's plane and left the box through it (fixed in Scene::spawnRay's ray origin).
    // Power: kRes^2 kSpp paths of D bounces, 3.84e7 bounces; at the old rate the chance that
    // none ends early (the test passes on the old code) is exp(-1.1e-7 x 3.84e7) = 1.5 %.
    // pt and lt are not exact per sample, cost 1.6 and 1 times pt-bsdf per bounce and would
    // need at least as many bounces to meet the rare early ends: they are not run here.
    // Measured after the fix (4 x 4 pixels, D = 1e5): pt +0.007 % and +0.004 % (16 spp, standard
    // error 0.007 %); lt +0.08 .. +0.11 % in four runs (16 and 64 spp), whose spread at D = 1e4
    // is about 0.07 %: whether lt keeps a small excess is left open (issue 16).
    std::string text = scenetext::readText(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/furnace.scene");
    const size_t at = text.find("albedo 0.5 0.5 0.5");
    REQUIRE_MESSAGE(at != std::string::npos, "scenes/furnace.scene no longer says 'albedo 0.5 0.5 0.5'");
    text.replace(at, 18, "albedo 1 1 1");
    constexpr int kRes = 4, kSpp = 24, kDepth = 100000;
    Scene scene = parseScene(scenetext::transformScene(text, 1.0, 0.0, kRes), "furnace-albedo-1.scene");
    scene.settings.maxDepth = kDepth;
    const double exact = kDepth + 1.0;
    const Result r = renderWith(scene, "pt-bsdf", kSpp);
    CHECK_MESSAGE(r.stats.bad() == 0, "pt-bsdf: " << r.stats.bad() << " NaN/Inf samples");
    int shortPixels = 0;
    double lost = 0.0;  // bounces lost, summed over the pixels' samples
    for (const Color& c : r.mean.pixels)
        if (double(c.r) != exact || double(c.g) != exact || double(c.b) != exact) {
            ++shortPixels;
            lost += (exact - double(c.g)) * kSpp;
        }
    CHECK_MESSAGE(shortPixels == 0, "pt-bsdf: " << shortPixels << " of " << kRes * kRes
                                                << " pixels are not exactly D + 1 = " << exact << " (image mean "
                                                << meanValue(r.mean) << ", " << lost
                                                << " bounces missing): paths ended before the maximum depth");
}

TEST_CASE("extreme: a thin-lens camera: every integrator renders it finite and not black, or refuses it by name") {
    // scenes/cornell-lens.scene (a lens of radius 40 mm, the box's spheres: glossy, mirror,
    // diffuse) at 8 x 8, and the same with a lens of 1e-3 mm (nearly a pinhole: the densities
    // 1 / (pi r^2) near 3e5) and one of 400 mm (wider than the box; most lens points see the
    // outside): an integrator that says it renders a camera model (IntegratorCaps::cameraModels) must give
    // no NaN or Inf (and pt, lt, bpt, drt a non-black image); every other one must refuse the
    // scene with an InputError that names it and the camera line, never render it as if the
    // camera were a pinhole.
    const std::string text = scenetext::readText(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/cornell-lens.scene");
    for (const char* lens : {"lens 40", "lens 0.001", "lens 400"}) {
        std::string t = text;
        const size_t at = t.find("lens 40");
        REQUIRE_MESSAGE(at != std::string::npos, "scenes/cornell-lens.scene no longer says 'lens 40'");
        t.replace(at, 7, lens);
        const Scene scene = parseScene(scenetext::transformScene(t, 1.0, 0.0, 8), "cornell-lens.scene");
        REQUIRE(!scene.camera.isPinhole());
        for (const std::string& algo : allAlgorithms()) {
            CAPTURE(lens);
            CAPTURE(algo);
            if (!makeIntegrator(algo)->caps.cameraModels) {
                try {
                    renderWith(scene, algo, 1);
                    FAIL_CHECK(algo << " does not render a thin lens but rendered the scene instead of refusing it");
                } catch (const InputError& e) {
                    const std::string msg = e.what();
                    CHECK_MESSAGE((msg.find("cornell-lens.scene:9:") != std::string::npos &&
                                   msg.find("'" + algo + "' cannot render") != std::string::npos),
                                  "expected an error naming the camera line and '" << algo << "', got: " << msg);
                }
                continue;
            }
            if (refuses(algo, scene)) continue;  // refused for what else the scene holds (radiosity: the spheres)
            const Result r = renderWith(scene, algo, 2);
            CHECK_MESSAGE(r.stats.bad() == 0,
                          algo << ": " << r.stats.nan << " NaN and " << r.stats.inf << " Inf samples");
            // (2 samples of BSDF sampling alone, or of one path length, may well miss the light.)
            if (algo == "eyelight" || algo == "normals" || algo == "pt" || algo == "lt" || algo == "bpt" ||
                algo == "drt")
                CHECK_MESSAGE(!firstNonBlack(r.mean).empty(), algo << " renders the lens box black");
        }
    }
}
