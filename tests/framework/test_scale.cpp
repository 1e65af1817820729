// Scale invariance: the Cornell box scaled by 1e-4 and 1e4, and translated by (1e5, 1e5, 1e5),
// must render the same image as the original (relative ray offsets and the watertight test;
// absolute epsilons fail this). Two renderers:
//  - eyelight (first hits only): tests camera rays, the BVH and the triangle test;
//  - a probe with secondary rays, since eyelight never spawns a ray from a surface and so cannot
//    show self-intersection ("acne") or rays slipping through surfaces ("leaks"): per sample,
//    R = 1 if a shadow ray (Scene::spawnRayTo) to a point on the light is unoccluded,
//    G = |cos| at the hit of a cosine-distributed bounce ray (Scene::spawnRay),
//    B = that bounce ray's hit distance / scene radius (acne: a tiny distance).
// Same seed, same random numbers: the renders differ only by float rounding of the geometry.
#include <doctest/doctest.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include "eyelight.h"
#include "render.h"
#include "scene_loader.h"
#include "scene_text.h"

using namespace ps;
using ps::scenetext::readText;
using ps::scenetext::transformScene;

namespace {

constexpr int kRes = 64;
constexpr int kSpp = 4;
constexpr uint64_t kSeed = 20240607;

// The secondary-ray probe described at the top.
class SecondaryRayProbe : public PixelIntegrator {
public:
    Color Li(const Scene& scene, const Ray& ray, Rng& rng) const override {
        Ray r = ray;
        SurfacePoint sp;
        if (!scene.intersect(r, sp) || sp.light >= 0) return Color(0.0f);
        const float side = glm::dot(sp.n, -ray.d) >= 0.0f ? 1.0f : -1.0f;  // the side the eye sees
        Color c(0.0f);

        // R: a shadow ray to a uniformly chosen point of the first area light.
        const float u0 = rng.uniform(), u1 = rng.uniform(), u2 = rng.uniform();
        for (const Light& light : scene.lights) {
            if (light.kind != LightKind::Area) continue;
            const size_t k = std::min(static_cast<size_t>(u0 * light.prims.size()), light.prims.size() - 1);
            const uint32_t prim = light.prims[k];
            const Triangle& tri = scene.triangles[scene.prims[prim].index];
            const float su = std::sqrt(u1), b1 = 1.0f - su, b2 = u2 * su;
            const SurfacePoint q = scene.surfacePoint(prim, (1.0f - b1 - b2) * tri.p0 + b1 * tri.p1 + b2 * tri.p2);
            const Vec3 toLight = q.p - sp.p;
            if (glm::dot(q.n, -toLight) > 0.0f && side * glm::dot(sp.n, toLight) > 0.0f &&
                !scene.occluded(scene.spawnRayTo(sp, q)))
                c.r = 1.0f;
            break;
        }

        // G, B: a cosine-distributed bounce ray on the eye's side.
        const float v1 = rng.uniform(), v2 = rng.uniform();
        const float rad = std::sqrt(v1), phi = 2.0f * kPi * v2;
        const Vec3 n = side * sp.n;
        const Vec3 d =
            glm::normalize(Frame(n).toWorld(Vec3(rad * std::cos(phi), rad * std::sin(phi), std::sqrt(1.0f - v1))));
        Ray bounce = scene.spawnRay(sp, d);
        SurfacePoint hit;
        if (scene.intersect(bounce, hit)) {
            c.g = std::abs(glm::dot(hit.n, d));
            c.b = std::min(bounce.tMax / scene.radius, 1.0f);
        }
        return c;
    }
};

Image renderText(const std::string& text, PixelIntegrator& integrator) {
    const Scene scene = parseScene(text, "cornell-box-transformed.scene");
    RenderOptions opt;
    opt.spp = kSpp;
    opt.seed = kSeed;
    const RenderResult res = render(scene, integrator, opt);
    CHECK(res.stats.bad() == 0);
    return res.film.mean();
}

struct Comparison {
    int pixels = 0, within = 0, blackWhereBright = 0, maxDiffX = -1, maxDiffY = -1;
    float maxDiff = 0.0f;
};

// Per pixel: every channel within absTol + relTol * |ref|; "black where bright": the
// reference's channel sum above 0.3 and the image's below 1 % of it.
Comparison compare(const Image& img, const Image& ref, float absTol, float relTol) {
    Comparison c;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const Color a = img.at(x, y), b = ref.at(x, y);
            bool ok = true;
            for (int ch = 0; ch < 3; ++ch) {
                const float diff = std::abs(a[ch] - b[ch]);
                ok = ok && diff <= absTol + relTol * std::abs(b[ch]);
                if (diff > c.maxDiff) {
                    c.maxDiff = diff;
                    c.maxDiffX = x;
                    c.maxDiffY = y;
                }
            }
            // SCALE_DEBUG=1 in the environment lists the pixels outside the tolerance.
            if (!ok && std::getenv("SCALE_DEBUG"))
                std::printf("pixel %d %d: img %g %g %g ref %g %g %g\n", x, y, a.r, a.g, a.b, b.r, b.g, b.b);
            const float sa = a.r + a.g + a.b, sb = b.r + b.g + b.b;
            if (sb > 0.3f && sa < 0.01f * sb) ++c.blackWhereBright;
            ++c.pixels;
            c.within += ok;
        }
    return c;
}

struct Case {
    const char* name;
    double scale, translate;
    float absTol, relTol;
};

// Scales 1e-4 and 1e4 change the coordinates' float rounding by ~6e-8 relative: normals and
// cosines agree to ~1e-6; only samples that land on an edge may switch surfaces. Tolerance
// 1e-4 + 1e-4 |ref| per channel.
// The translation by 1e5 moves every coordinate to where the float spacing is 2^-7 = 0.0078
// (mm): each vertex moves by up to 0.004 mm, which tilts the quads' normals by up to ~1e-5
// and shifts edges by ~1e-3 pixel. Tolerance 1e-3 + 1e-3 |ref|: ten times looser, still
// far below any visible change (a wrong normal, a missed surface or a shadow change >= 0.25).
const Case kCases[] = {
    {"scale 1e-4", 1e-4, 0.0, 1e-4f, 1e-4f},
    {"scale 1e4", 1e4, 0.0, 1e-4f, 1e-4f},
    {"translate 1e5", 1.0, 1e5, 1e-3f, 1e-3f},
};

void checkCase(const Case& cs, const Image& img, const Image& ref, float minFraction) {
    const Comparison c = compare(img, ref, cs.absTol, cs.relTol);
    INFO(std::string(cs.name) << ": " << c.within << " of " << c.pixels << " pixels within " << cs.absTol << " + "
                              << cs.relTol << " |ref|; largest difference " << c.maxDiff << " at pixel (" << c.maxDiffX
                              << ", " << c.maxDiffY << "); " << c.blackWhereBright
                              << " pixels black where the reference is bright");
    CHECK(c.within >= minFraction * c.pixels);
    CHECK(c.blackWhereBright == 0);
}

}  // namespace

TEST_CASE("scale: the transformation keeps the scene and moves what it should") {
    const std::string text = readText(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/cornell-box.scene");
    const Scene a = parseScene(transformScene(text, 1.0, 0.0, kRes), "a.scene");
    const Scene b = parseScene(transformScene(text, 1e4, 1e5, kRes), "b.scene");
    REQUIRE(a.triangles.size() == b.triangles.size());
    CHECK(a.camera.width() == kRes);
    CHECK(a.camera.height() == kRes);
    CHECK(b.camera.position().x == doctest::Approx(278.0 * 1e4 + 1e5).epsilon(1e-6));
    CHECK(b.triangles[0].p0.x == doctest::Approx(a.triangles[0].p0.x * 1e4 + 1e5).epsilon(1e-6));
    CHECK(b.radius == doctest::Approx(a.radius * 1e4).epsilon(1e-4));
}

TEST_CASE("scale: eyelight renders of the Cornell box at scales 1e-4, 1e4 and translated by 1e5 agree") {
    const std::string text = readText(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/cornell-box.scene");
    EyeLight eyelight;
    const Image ref = renderText(transformScene(text, 1.0, 0.0, kRes), eyelight);
    for (const Case& cs : kCases) {
        const Image img = renderText(transformScene(text, cs.scale, cs.translate, kRes), eyelight);
        checkCase(cs, img, ref, 0.99f);
    }
}

TEST_CASE("scale: shadow and bounce rays (no acne, no leaks) at scales 1e-4, 1e4 and translated by 1e5") {
    const std::string text = readText(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/cornell-box.scene");
    SecondaryRayProbe probe;
    const Image ref = renderText(transformScene(text, 1.0, 0.0, kRes), probe);
    // The probe itself must see something: lit and shadowed pixels, bounce hits everywhere.
    int lit = 0, shadowed = 0;
    for (const Color& c : ref.pixels) {
        lit += c.r > 0.99f;       // all 4 shadow rays reached the light
        shadowed += c.r < 0.01f;  // none did (or the pixel shows the light itself)
    }
    CHECK(lit > kRes * kRes / 4);
    CHECK(shadowed > kRes * kRes / 50);
    for (const Case& cs : kCases) {
        const Image img = renderText(transformScene(text, cs.scale, cs.translate, kRes), probe);
        checkCase(cs, img, ref, 0.99f);
    }
}
