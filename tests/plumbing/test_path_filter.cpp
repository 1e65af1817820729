// `--paths`: Heckbert's path expressions applied by pt, lt, bpt and pm (lesson 11's plumbing,
// lessons/11-classics/path_filter.h). What must hold, and how it is checked:
//   - exactness of the filter: with the same seed, pt's images of expressions that partition the
//     paths add up to pt's image (to float rounding: each sample's terms are summed in another
//     order); an expression that matches every path renders pt's, bpt's and pm's images bit for
//     bit; ending walks at dead states (pruning) changes no bit of pt, lt and pm;
//   - the algorithms agree under a filter: lt and bpt against pt (per-pixel z-tests), where each
//     can sample the paths;
//   - the caustics of the Cornell spheres (LS+DE) are exactly 0 in the pixels whose first surface
//     is specular and not 0 on the floor's caustic, in every algorithm; a scene without specular
//     surfaces has no caustic at all (black);
//   - Veach's pyramid under `LDE` holds paths of length 2 only;
//   - every algorithm either honours an expression or refuses it;
//   - through a thin lens (lesson 11, scenes/cornell-lens.scene) all of it holds too: pt's and bpt's
//     images of a partition add up to their unfiltered images (bpt's technique t = 0, a light
//     subpath that reaches the lens, is filtered with the lens point as its E), `L.*E` renders
//     bpt and pm bit for bit and lt to float rounding, the pyramid's t = 0 cells keep only their
//     matching length, and every filtered form renders a lens where its algorithm does.
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>
#include "07-bidirectional/bpt.h"
#include "errors.h"
#include "11-classics/path_filter.h"
#include "format.h"
#include "lesson_files.h"
#include "render.h"
#include "render_helpers.h"
#include "scene_loader.h"
#include "scene_text.h"
#include "seed.h"
#include "statistics.h"

using namespace ps;

namespace {

struct Result {
    Image mean, variance;
    SampleStats stats;
};

Result renderWith(const Scene& scene, const std::string& algo, const std::string& paths, int spp, uint64_t seed,
                  int threads = 1) {
    std::unique_ptr<Integrator> integrator;
    if (paths.empty()) {
        integrator = makeIntegrator(algo);
    } else {
        integrator = makeIntegrator(algo, {{"paths", paths}});
    }
    RenderOptions opt;
    opt.spp = spp;
    opt.seed = seed;
    opt.threads = threads;
    const RenderResult r = render(scene, *integrator, opt);
    return {r.film.mean(), r.film.varianceOfMean(), r.stats};
}

bool sameBits(const Image& a, const Image& b) {
    if (a.pixels.size() != b.pixels.size()) return false;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            if (std::memcmp(&a.pixels[i][c], &b.pixels[i][c], sizeof(float)) != 0) return false;
    return true;
}

double total(const Image& img) {
    double t = 0.0;
    for (const Color& c : img.pixels) t += double(c.r) + c.g + c.b;
    return t;
}

Scene spheres(int res = 16) { return testfiles::loadSceneAt("scenes/cornell-spheres.scene", res, res); }

// scenes/cornell-lens.scene: the Cornell box through a thin lens of radius 40 mm, with a glossy
// (Phong), a mirror and a diffuse sphere (every vertex type).
Scene lensBox(int res = 16) {
    const Scene scene = testfiles::loadSceneAt("scenes/cornell-lens.scene", res, res);
    REQUIRE_MESSAGE(!scene.camera.isPinhole(), "scenes/cornell-lens.scene has no thin lens any more");
    return scene;
}

// The worst relative difference, per pixel channel, between the sum of parts and whole, as "pixel
// P channel C: parts add to X, whole Y" (with the names given); worst gets the relative difference.
std::string worstSum(const std::vector<Image>& parts, const Image& whole, double& worst,
                     const std::string& partsName = "parts add to", const std::string& wholeName = "whole") {
    worst = 0.0;
    std::string where;
    for (size_t i = 0; i < whole.pixels.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            double sum = 0.0;
            for (const Image& r : parts) sum += double(r.pixels[i][ch]);
            const double a = double(whole.pixels[i][ch]);
            const double rel = std::abs(sum - a) / (std::abs(a) + 1e-6);
            if (rel > worst) {
                worst = rel;
                where = "pixel " + std::to_string(i) + " channel " + std::to_string(ch) + ": " + partsName + " " +
                        fmt::num(sum, 9) + ", " + wholeName + " " + fmt::num(a, 9);
            }
        }
    return where;
}

// Every string L t_1 .. t_n E with n <= 7: whether the expressions partition them.
void requirePartition(const std::vector<std::string>& parts) {
    std::vector<std::string> mids = {""};
    for (size_t i = 0; i < mids.size(); ++i)
        if (mids[i].size() < 7)
            for (char c : std::string("DGS")) mids.push_back(mids[i] + c);
    std::vector<PathExpression> e;
    for (const std::string& p : parts) e.emplace_back(p);
    for (const std::string& m : mids) {
        int n = 0;
        for (const PathExpression& x : e) n += x.matches("L" + m + "E");
        REQUIRE_MESSAGE(n == 1, "L" << m << "E is matched by " << n << " of the expressions");
    }
}

}  // namespace

TEST_CASE("paths filter: pt's images of a partition of the paths add up to pt's image (same seed)") {
    const struct {
        const char* scene;
        std::vector<std::string> parts;
    } cases[] = {
        {"scenes/cornell-spheres.scene", {"LE", "LDE", "L(S|G|D.).*E"}},
        {"scenes/cornell-spheres.scene", {"L[DG]*E", "L.*S.*E"}},
        {"scenes/cornell-glossy.scene", {"L[DS]*E", "L.*G.*E"}},
    };
    for (const auto& c : cases) {
        requirePartition(c.parts);
        const Scene scene = testfiles::loadSceneAt(c.scene, 16, 16);
        const Result all = renderWith(scene, "pt", "", 16, 3);
        std::vector<Result> parts;
        for (const std::string& p : c.parts) parts.push_back(renderWith(scene, "pt", p, 16, 3));
        double worst = 0.0;
        std::string where;
        for (size_t i = 0; i < all.mean.pixels.size(); ++i)
            for (int ch = 0; ch < 3; ++ch) {
                double sum = 0.0;
                for (const Result& r : parts) sum += double(r.mean.pixels[i][ch]);
                const double a = double(all.mean.pixels[i][ch]);
                const double rel = std::abs(sum - a) / (std::abs(a) + 1e-6);
                if (rel > worst) {
                    worst = rel;
                    where = "pixel " + std::to_string(i) + " channel " + std::to_string(ch) + ": parts add to " +
                            fmt::num(sum, 9) + ", pt " + fmt::num(a, 9);
                }
            }
        // Each sample adds at most maxdepth + 1 = 9 emission and 8 light-sample terms in float, in
        // another order than pt: a relative difference of a few float epsilons (1.2e-7 each).
        CHECK_MESSAGE(worst < 5e-6, c.scene << ": the worst " << where << " (relative " << worst << ")");
    }
}

TEST_CASE(
    "paths filter: through a thin lens, pt's and bpt's images of a partition add up to their images (bpt's t = 0 "
    "included)") {
    // scenes/cornell-lens.scene at 16 x 16, same seed: pt's camera rays and bpt's camera subpaths
    // start at lens points, and bpt gains the technique t = 0 of lesson 11 (light subpaths that
    // reach the lens), which the expression filters like every other technique, with the lens
    // point as the path's E. Were t = 0 not filtered, every part would hold all of its paths and
    // the parts would add up to more than bpt. The lens is widened to 200 mm here so that t = 0
    // carries a visible share of bpt's image (at 40 mm it carries little, lesson 11's README).
    std::string text = testfiles::readText(testfiles::sourcePath("scenes/cornell-lens.scene"));
    const size_t at = text.find("lens 40");
    REQUIRE_MESSAGE(at != std::string::npos, "scenes/cornell-lens.scene no longer says 'lens 40'");
    text.replace(at, 7, "lens 200");
    const Scene scene = parseScene(scenetext::withResolution(text, 16, 16), "cornell-lens-200.scene");
    const std::vector<std::vector<std::string>> partitions = {{"LE", "LDE", "L(S|G|D.).*E"}, {"L[DS]*E", "L.*G.*E"}};
    for (const char* algo : {"pt", "bpt"})
        for (const std::vector<std::string>& parts : partitions) {
            requirePartition(parts);
            const int spp = std::string(algo) == "pt" ? 16 : 4;
            const Result all = renderWith(scene, algo, "", spp, 3);
            REQUIRE_MESSAGE(total(all.mean) > 0.0, algo << " renders the lens box black");
            std::vector<Image> images;
            std::string names;
            for (const std::string& p : parts) {
                images.push_back(renderWith(scene, algo, p, spp, 3).mean);
                names += (names.empty() ? "'" : ", '") + p + "'";
            }
            double worst = 0.0;
            const std::string where = worstSum(images, all.mean, worst);
            // As for the pinhole (above): a few float epsilons, the terms added in another order.
            CHECK_MESSAGE(worst < 5e-6, algo << " through the lens, parts " << names << ": the worst " << where
                                             << " (relative " << worst << ")");
        }
}

TEST_CASE("paths filter: through a thin lens, lt --paths 'L.*E' agrees with lt (per-pixel z-test)") {
    // lt joins every vertex of a light path to one lens point drawn before the walk (lesson 5's
    // traceLightPath); its filtered form is lesson 7's light subpath joined by connectCamera to one
    // lens point per path. The two walks no longer draw the same paths (lesson 7's subpaths survive
    // by the material, Eq. 7.1a; lt's walk by Eq. 3.5), so they are compared in expectation: a
    // per-pixel z-test of two independent renders (zTestImages: every channel at the Sidak level,
    // 99.75 % must pass) at alpha = 0.01 (0 false failures in 31 seeds). A filtered lt that joins
    // every path to the lens centre (a pinhole's image: the box is out of focus at its back wall),
    // or that loses 10 % of its value, fails it (tried: 6 of 6 seeds each).
    const Scene scene = lensBox();
    REQUIRE(!scene.camera.isPinhole());
    const uint64_t seed = testseed::seed(5);
    const Result plain = renderWith(scene, "lt", "", 256, seed, 2),
                 filtered = renderWith(scene, "lt", "L.*E", 256, seed + 1, 2);
    REQUIRE_MESSAGE(total(plain.mean) > 0.0, "lt renders the lens box black");
    CHECK_MESSAGE((plain.stats.bad() == 0 && filtered.stats.bad() == 0), "NaN/Inf samples");
    const stats::ZTestResult z = stats::zTestImages(filtered.mean, filtered.variance, plain.mean, plain.variance, 0.01);
    CHECK_MESSAGE(z.passed, "lt --paths 'L.*E' against lt through the lens: " << z.report << " (sums "
                                                                              << fmt::num(total(filtered.mean)) << ", "
                                                                              << fmt::num(total(plain.mean)) << ")");
}

TEST_CASE("paths filter: an expression matching every path renders pt, bpt and pm bit for bit (pinhole and lens)") {
    // Through the lens, bpt's t = 0 (lesson 11) asks the expression too, with the lens point as E.
    for (const Scene& scene : {spheres(), lensBox()})
        for (const char* algo : {"pt", "bpt", "pm"})
            for (const char* every : {"L.*E", "L(D|G|S)*E"}) {
                const std::string cam = scene.camera.isPinhole() ? "pinhole" : "thin lens";
                const Result plain = renderWith(scene, algo, "", 2, 5, 2),
                             filtered = renderWith(scene, algo, every, 2, 5, 2);
                CHECK_MESSAGE(sameBits(plain.mean, filtered.mean), cam << ": " << algo << " --paths '" << every
                                                                       << "' differs from " << algo << " (image sums "
                                                                       << fmt::num(total(filtered.mean), 12) << " and "
                                                                       << fmt::num(total(plain.mean), 12) << ")");
                CHECK_MESSAGE(total(plain.mean) > 0.0, cam << ": " << algo << " renders black");
            }
}

TEST_CASE("paths filter: ending walks at dead states changes nothing (pt, lt, pm with and without --no-prune)") {
    Scene pruned = spheres();
    Scene unpruned = pruned;
    unpruned.settings.prune = false;
    for (const char* algo : {"pt", "lt", "pm"})
        for (const char* e : {"LDE", "LS+DE", "L.*S.*E", "LD+E"}) {
            const Result a = renderWith(pruned, algo, e, 2, 9, 2), b = renderWith(unpruned, algo, e, 2, 9, 2);
            CHECK_MESSAGE(sameBits(a.mean, b.mean), algo << " --paths '" << e << "': pruned and unpruned images differ "
                                                         << "(sums " << fmt::num(total(a.mean), 12) << " and "
                                                         << fmt::num(total(b.mean), 12) << ")");
        }
}

TEST_CASE("paths filter: lt and bpt agree with pt under the same expression (per-pixel z-tests)") {
    // The Cornell spheres at 16 x 16, maxdepth 8. Each comparison is a per-pixel z-test of two
    // independent renders (zTestImages: every channel at the Sidak level over the channels, 99.75 %
    // must pass), at alpha = 0.01 with Sidak over the comparisons. lt cannot see a path whose last
    // vertex before the eye is specular, so it is compared on expressions ending in D; the caustics
    // (LS+DE), which pt samples only by hitting the lamp through the glass or in the mirror, lt
    // against bpt; and what is seen in the spheres (L[DG]+S+E), bpt against pt. (Not L.*S.*E: its
    // caustics on the ceiling, the lamp's light reflected up by the mirror sphere, are rare events
    // for pt whose variance 1024 samples underestimate, and the z-test rejects pt, not bpt.) bpt
    // renders LS+DE with 2048 samples: with 512 a caustic pixel that bpt reaches rarely had its
    // variance underestimated (lt about 5 times bpt's mean at one pixel, z about 5) in 3 seeds of 41
    // (1 of 41 before lesson 7's subpaths survived by Eq. 7.1a); with 2048, in 0 of 41.
    const Scene scene = spheres();
    const struct {
        const char* expr;
        const char* a;
        int sppA;
        const char* b;
        int sppB;
    } cases[] = {
        {"LDE", "lt", 1024, "pt", 1024},   {"LDE", "bpt", 256, "pt", 1024},       {"LD+DE", "lt", 1024, "pt", 1024},
        {"LD+DE", "bpt", 256, "pt", 1024}, {"L[DG]+S+E", "bpt", 256, "pt", 1024}, {"LS+DE", "lt", 2048, "bpt", 2048},
    };
    const double alpha = stats::sidak(0.01, int(std::size(cases)));
    uint64_t seed = testseed::seed(100);
    for (const auto& c : cases) {
        const Result a = renderWith(scene, c.a, c.expr, c.sppA, ++seed, 2),
                     b = renderWith(scene, c.b, c.expr, c.sppB, ++seed, 2);
        CHECK_MESSAGE((a.stats.bad() == 0 && b.stats.bad() == 0), c.expr << ": NaN/Inf samples");
        REQUIRE_MESSAGE(total(b.mean) > 0.0, c.b << " --paths '" << c.expr << "' renders black");
        const stats::ZTestResult z = stats::zTestImages(a.mean, a.variance, b.mean, b.variance, alpha);
        CHECK_MESSAGE(z.passed, c.a << " against " << c.b << " under '" << c.expr << "': " << z.report << " (sums "
                                    << fmt::num(total(a.mean)) << ", " << fmt::num(total(b.mean)) << ")");
    }
}

TEST_CASE(
    "paths filter: the caustics (LS+DE) are 0 where the eye meets a specular surface first, not 0 on the "
    "floor's caustic, and absent without specular surfaces") {
    const Scene scene = spheres(24);
    const std::vector<bool> specularFirst = testrender::pixelsWhere(scene, true, [&](bool hit, const SurfacePoint& sp) {
        return hit && scene.materials[size_t(sp.material)].isDelta();
    });
    // The caustic under the glass sphere: the 4 brightest floor pixels of lt's LS+DE image.
    const Result ref = renderWith(scene, "lt", "LS+DE", 256, 41, 2);
    const std::vector<bool> floorOnly =
        testrender::pixelsWhere(scene, true, [&](bool hit, const SurfacePoint& sp) { return hit && sp.p.y < 1.0f; });
    std::vector<size_t> order;
    for (size_t i = 0; i < ref.mean.pixels.size(); ++i)
        if (floorOnly[i]) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        return total(Image(1, 1, ref.mean.pixels[a])) > total(Image(1, 1, ref.mean.pixels[b]));
    });
    REQUIRE(order.size() >= 4);
    for (const char* algo : {"pt", "lt", "bpt", "pm"}) {
        // pt finds a caustic only by hitting the lamp through the glass: more samples.
        const Result r = renderWith(scene, algo, "LS+DE", std::string(algo) == "pt" ? 2048 : 32, 43, 2);
        int nonZero = 0;
        for (size_t i = 0; i < r.mean.pixels.size(); ++i)
            if (specularFirst[i] && !isBlack(r.mean.pixels[i])) ++nonZero;
        CHECK_MESSAGE(nonZero == 0,
                      algo << " --paths LS+DE: " << nonZero << " pixels whose first surface is specular are not black");
        for (size_t j = 0; j < 4; ++j)
            CHECK_MESSAGE(!isBlack(r.mean.pixels[order[j]]),
                          algo << " --paths LS+DE: the caustic pixel " << order[j] << " is black");
    }
    const Scene box = testfiles::loadSceneAt("scenes/cornell-box.scene", 8, 8);
    for (const char* algo : {"pt", "lt", "bpt", "pm"}) {
        Scene unpruned = box;
        unpruned.settings.prune = false;
        for (const Scene* s : {&box, static_cast<const Scene*>(&unpruned)}) {
            const Result r = renderWith(*s, algo, "LS+DE", 2, 47);
            CHECK_MESSAGE(total(r.mean) == 0.0, algo << " --paths LS+DE on the Cornell box (no specular surface)"
                                                     << (s->settings.prune ? "" : " with --no-prune")
                                                     << ": expected black, got sum " << total(r.mean));
        }
    }
}

TEST_CASE("paths filter: Veach's pyramid under LDE holds the paths of length 2 only (pinhole; lens: t = 0 too)") {
    // Through a thin lens (scenes/cornell-lens.scene, its lens widened to 200 mm so that light
    // subpaths reach it often) the row's last technique, t = 0, samples L D E as well.
    std::string text = testfiles::readText(testfiles::sourcePath("scenes/cornell-lens.scene"));
    const size_t at = text.find("lens 40");
    REQUIRE_MESSAGE(at != std::string::npos, "scenes/cornell-lens.scene no longer says 'lens 40'");
    text.replace(at, 7, "lens 200");
    for (const Scene& scene : {testfiles::loadSceneAt("scenes/cornell-box.scene", 8, 8),
                               parseScene(scenetext::withResolution(text, 8, 8), "cornell-lens-200.scene")}) {
        const bool lens = !scene.camera.isPinhole();
        CAPTURE(lens);
        const PathExpression e("LDE");
        BptOptions opt;
        opt.techniqueFilter = [&](const Subpath& light, const Subpath& camera, int s, int t) {
            return bptPathMatches(e, scene, light, camera, s, t);
        };
        const TechniqueImages t = renderTechniques(scene, 3, 16, 5, 1, opt);
        for (int k = 1; k <= 3; ++k)
            for (int s = 0; s <= k + 1; ++s) {
                const double sum = total(t.unweighted[size_t(techniqueIndex(s, k))]);
                if (k == 2 && s >= 0 && s <= (lens ? 3 : 2))
                    CHECK_MESSAGE(sum > 0.0, "technique (" << s << ", " << k + 1 - s << ") of LDE is black");
                else if (k != 2)
                    CHECK_MESSAGE(sum == 0.0, "technique (" << s << ", " << k + 1 - s << "), length " << k
                                                            << ": LDE has length 2, expected black, got sum " << sum);
            }
    }
}

TEST_CASE("paths filter: every algorithm honours an expression or refuses it, never ignores it") {
    const AlgorithmOptions lde = {{"paths", "LDE"}};
    const Scene scene = spheres(8);
    // The algorithms the option --paths names (another option may take others).
    const AlgorithmOption* paths = Registry<AlgorithmOption>::find("paths");
    REQUIRE(paths);
    const std::vector<std::string> offered = paths->algorithms();
    std::vector<std::string> honoured;
    for (const IntegratorInfo& info : integratorList()) {
        CAPTURE(info.name);
        if (std::find(offered.begin(), offered.end(), info.name) != offered.end()) {
            CHECK(takesAlgorithmOption(info.name));
            honoured.push_back(info.name);
            const std::unique_ptr<Integrator> i = makeIntegrator(info.name, lde);
            CHECK(carriedPaths(info.name, scene, lde) == "LDE");
            // A camera model (a thin lens): the filtered form renders one where the algorithm does,
            // so that a lens scene is never refused for --paths with an algorithm --paths offers.
            CHECK_MESSAGE(i->caps.cameraModels == makeIntegrator(info.name)->caps.cameraModels,
                          info.name << " --paths: renders a camera model " << i->caps.cameraModels << ", " << info.name
                                    << " alone " << makeIntegrator(info.name)->caps.cameraModels);
            CHECK_MESSAGE(i->name == info.name, "the filtered form's name is '" << i->name << "'");
        } else {
            bool refused = false;
            try {
                makeIntegrator(info.name, lde);
            } catch (const OptionError& err) { refused = std::string(err.what()).find("--paths") != std::string::npos; }
            CHECK_MESSAGE(refused, info.name << " neither honours --paths nor refuses it");
        }
    }
    for (const char* must : {"pt", "lt", "bpt", "bpt-balance", "bpt-full", "pm"})
        CHECK_MESSAGE(std::find(honoured.begin(), honoured.end(), must) != honoured.end(),
                      must << " has no filtered form");
    for (const char* refuses :
         {"pssmlt", "mmlt", "pt-adrrs", "path-s1", "pt-nee", "pt-bsdf", "whitted", "ppm", "pm-ic"})
        CHECK_MESSAGE(std::find(honoured.begin(), honoured.end(), refuses) == honoured.end(),
                      refuses << " claims to honour --paths");
}
