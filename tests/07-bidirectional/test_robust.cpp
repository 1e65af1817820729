// Lesson 7, graded: what the scene does not need is left out exactly (pruning, Eq. 7.12);
// close vertices in corners make no fireflies (the 1/d^2 of the connection's G is cancelled by
// MIS weights computed with the same pdf functions, Eq. 7.3); no NaN or Inf anywhere; the image
// does not depend on the number of threads.
#include "lesson07.h"
#include "seed.h"

using namespace lesson07;

namespace {

// Pixels whose 3 x 3 neighbourhood sees no specular surface (see test_cornell.cpp).
std::vector<bool> awayFromSpecular(const ps::Scene& scene) {
    const int w = scene.camera.width(), h = scene.camera.height();
    const std::vector<bool> spec = ps::testrender::pixelsWhere(scene, false, [&](bool hit, const ps::SurfacePoint& sp) {
        return hit && scene.materials[size_t(sp.material)].isDelta();
    });
    std::vector<bool> clear(size_t(w) * h, true);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx >= 0 && yy >= 0 && xx < w && yy < h && spec[size_t(yy) * w + xx])
                        clear[size_t(y) * w + x] = false;
                }
    return clear;
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

bool mentions(const std::vector<std::string>& lines, const std::string& what) {
    for (const std::string& l : lines)
        if (l.find(what) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST_CASE(
    "pruning is exact: pruned and unpruned renders agree with a point light and with specular spheres (z-tests) [2 pts]") {
    for (const auto& sceneAndSpp :
         std::vector<std::pair<std::string, int>>{{"cornell-point-light", 256}, {"cornell-spheres", 384}}) {
        const std::string& name = sceneAndSpp.first;  // named, not bound: clang < 16 captures no binding in a lambda
        const int iterations = sceneAndSpp.second;
        ps::Scene pruned = loadSceneAt("scenes/" + name + ".scene", 24, 24);
        ps::Scene full = pruned;
        full.settings.prune = false;
        const std::unique_ptr<ps::Integrator> bpt = ps::makeIntegrator("bpt");
        const std::vector<std::string> left = bpt->leftOut(pruned);
        CHECK_MESSAGE(bpt->leftOut(full).empty(), name << " with --no-prune: expected bpt to leave nothing out");
        if (name == "cornell-point-light")
            CHECK_MESSAGE(mentions(left, "s = 0"),
                          name << ": expected bpt to leave out the s = 0 techniques (no light can be hit)");
        else
            CHECK_MESSAGE(mentions(left, "specular"),
                          name << ": expected bpt to leave out connections at specular vertices");
        const Render a = render(pruned, "bpt", iterations, ps::testseed::seed(7301));
        const Render b = render(full, "bpt", iterations, ps::testseed::seed(7302));
        CHECK_MESSAGE(a.stats.bad() + b.stats.bad() == 0, name << ": expected no NaN or Inf samples, got "
                                                               << a.stats.bad() << " pruned and " << b.stats.bad()
                                                               << " unpruned");
        CHECK_MESSAGE(total(a.mean) > 0.0, name << ": expected a lit image, got a black one");
        const std::vector<bool> mask = awayFromSpecular(pruned);
        const ps::stats::ZTestResult z = ps::stats::zTestImages(
            select(a.mean, mask), select(a.variance, mask), select(b.mean, mask), select(b.variance, mask), alpha());
        CHECK_MESSAGE(z.passed, name << " (24 x 24, " << iterations
                                     << " spp; pixels away from specular surfaces): expected the pruned "
                                        "render (a) to equal the unpruned one (b) within their noise, got\n  "
                                     << z.report);
    }
}

TEST_CASE(
    "close vertices in a corner make no fireflies: max pixel below 2 x the path tracer's, mean within 10 % [2 pts]") {
    // The Cornell box seen from inside, 11 cm from the corner of floor, back wall and green
    // wall: connections between vertices a few mm apart have a huge G = cos cos / d^2. With
    // MIS weights from the same pdfs (Eq. 7.3) the techniques that sample such paths well take
    // them over; equal weights (1 / number of techniques) give pixels 14 x too bright here.
    std::string text = readText(sourcePath("scenes/cornell-box.scene"));
    text = ps::scenetext::replaceLines(text, "camera",
                                       "camera eye 60 60 480  target 0 0 559.2  up 0 1 0  fov 40  resolution 16 16");
    const ps::Scene scene = ps::parseScene(text, sourcePath("scenes/cornell-box.scene"));
    const Render b = render(scene, "bpt", 64, ps::testseed::seed(7401));
    const Render p = render(scene, "pt", 1024, ps::testseed::seed(7402));
    const auto stats = [](const ps::Image& img, int& at) {
        double mx = -1.0, mean = 0.0;
        for (size_t i = 0; i < img.pixels.size(); ++i) {
            const double l = ps::luminance(img.pixels[i]);
            mean += l;
            if (l > mx) {
                mx = l;
                at = int(i);
            }
        }
        return std::make_pair(mx, mean / double(img.pixels.size()));
    };
    int atB = 0, atP = 0;
    const std::pair<double, double> sB = stats(b.mean, atB), sP = stats(p.mean, atP);
    const double maxB = sB.first, meanB = sB.second, maxP = sP.first, meanP = sP.second;
    CHECK_MESSAGE(b.stats.bad() == 0, "bpt in the corner: expected no NaN or Inf samples, got " << b.stats.bad());
    CHECK_MESSAGE(meanB > 0.0, "bpt in the corner: expected a lit image, got a black one");
    CHECK_MESSAGE(maxB <= 2.0 * maxP,
                  "bpt in the corner (16 x 16, 64 spp): expected every pixel's luminance <= 2 x the path tracer's "
                  "brightest pixel ("
                      << num(maxP) << "), got " << num(maxB) << " at pixel (" << atB % 16 << ", " << atB / 16 << ")");
    CHECK_MESSAGE(std::abs(meanB - meanP) <= 0.1 * meanP,
                  "bpt in the corner: expected the mean luminance of the path tracer's image, "
                      << num(meanP) << " +- 10 %, got " << num(meanB));
}

TEST_CASE("no NaN or Inf in any scene of the course, and every image is lit [1 pt]") {
    for (const std::string name :
         {"cornell-box", "cornell-glossy", "cornell-small-light", "cornell-spheres", "cornell-point-light",
          "cornell-background", "glass-lamp", "veach-plates", "point-in-sphere", "furnace"}) {
        const ps::Scene scene = loadSceneAt("scenes/" + name + ".scene", 12, 12);
        for (const std::string algo : {"bpt", "bpt-balance", "bpt-full"}) {
            const Render r = render(scene, algo, 24, ps::testseed::seed(7501));
            CHECK_MESSAGE(r.stats.bad() == 0, algo << " on " << name << ": expected 0 NaN and 0 Inf samples, got "
                                                   << r.stats.nan << " NaN and " << r.stats.inf << " Inf");
            CHECK_MESSAGE(total(r.mean) > 0.0, algo << " on " << name << ": expected a lit image, got a black one");
        }
    }
    // A scene without lights: no light subpath, no light to connect to, a black image.
    const ps::Scene dark = ps::parseScene(
        "camera eye 0 1 -3  target 0 1 0  fov 60  resolution 8 8\n"
        "material white diffuse albedo 0.5 0.5 0.5\n"
        "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material white\n",
        "a floor without a light (test_robust.cpp)");
    const Render r = render(dark, "bpt", 4, ps::testseed::seed(7502));
    CHECK_MESSAGE((r.stats.bad() == 0 && total(r.mean) == 0.0),
                  "bpt on a floor without a light: expected a black image and 0 NaN or Inf samples, got the total "
                      << total(r.mean) << " and " << r.stats.bad() << " NaN or Inf");
}

TEST_CASE("the image does not depend on the number of threads [1 pt]") {
    const ps::Scene scene = loadSceneAt("scenes/cornell-spheres.scene", 16, 16);
    const Render one = render(scene, "bpt", 6, ps::testseed::seed(7601), 1);
    const Render two = render(scene, "bpt", 6, ps::testseed::seed(7601), 2);
    CHECK_MESSAGE(total(one.mean) > 0.0, "bpt on cornell-spheres: expected a lit image, got a black one");
    int differ = 0;
    for (size_t i = 0; i < one.mean.pixels.size(); ++i) differ += one.mean.pixels[i] != two.mean.pixels[i];
    CHECK_MESSAGE(differ == 0,
                  "bpt on cornell-spheres (16 x 16, 6 spp): expected identical images with 1 and 2 threads, "
                      << differ << " pixels differ");
}
