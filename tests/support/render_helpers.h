// Rendering in the graded tests, once for every lesson: a fixed-seed render of a named
// integrator through the framework's render loop, and the sums the tests compare.
#pragma once
#include <algorithm>
#include <memory>
#include <string>
#include <vector>
#include "bsdf.h"
#include "film.h"
#include "image.h"
#include "integrator.h"
#include "light.h"
#include "render.h"
#include "scene.h"

namespace ps::testrender {

// What a test keeps of a render: the image (mean over iterations), the variance of the mean
// per pixel (for z-tests), the NaN/Inf counts, and the algorithm's name (for messages).
struct Render {
    Image mean, variance;
    SampleStats stats;
    std::string algo = "";  // default: for a Render made from a RenderResult by hand
};

// Renders `spp` iterations of the named integrator with a fixed seed. One thread by default:
// the test images are tiny (a few thousand pixels per iteration), and with two threads the
// render loop's synchronisation after every iteration costs more than the work itself, badly so
// when CTest runs two tests at once (ctest -j2) or the machine is busy. The image does not
// depend on the thread count (framework/tasks.h).
inline Render render(const Scene& scene, const std::string& algo, int spp, uint64_t seed, int threads = 1) {
    std::unique_ptr<Integrator> integrator = makeIntegrator(algo);
    RenderOptions opt;
    opt.spp = spp;
    opt.seed = seed;
    opt.threads = threads;
    const RenderResult r = ps::render(scene, *integrator, opt);
    return {r.film.mean(), r.film.varianceOfMean(), r.stats, algo};
}

// r + g + b, in double.
inline double sum(const Color& c) { return double(c.r) + double(c.g) + double(c.b); }
// The sum of every channel of every pixel, in double.
inline double total(const Image& img) {
    double t = 0.0;
    for (const Color& c : img.pixels) t += sum(c);
    return t;
}

// Sums over blocks of b x b pixels, for z-tests of a technique that hits the light by chance
// (lesson 6's and 7's (0, k + 1)): it has a few hits per pixel, or none, and a per-pixel variance
// estimate of such heavy-tailed samples is unreliable (0 where no sample hit); sums over blocks
// are not. Variances add (the pixels are independent).
inline Image blocks(const Image& img, int b) {
    Image out(img.width / b, img.height / b);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) out.at(x / b, y / b) += img.at(x, y);
    return out;
}

// The pixels of img where mask is true, in a row (for z-tests on a part of an image).
inline Image select(const Image& img, const std::vector<bool>& mask) {
    int n = 0;
    for (bool m : mask) n += m;
    Image out(n, 1);
    int k = 0;
    for (size_t i = 0; i < img.pixels.size(); ++i)
        if (mask[i]) out.pixels[size_t(k++)] = img.pixels[i];
    return out;
}

// Per pixel of the scene's camera, row by row: rays through the 6 x 6 points of a grid over the
// pixel (its edges included), each tested with pred(hit, sp), sp the first surface the ray meets
// (hit false: none); true where `some` ray passes (all = false) or where every ray does (all =
// true). Test fixtures find with it the pixels that see a lamp, a specular surface, only the floor.
template <class Pred>
std::vector<bool> pixelsWhere(const Scene& scene, bool all, Pred&& pred) {
    const int w = scene.camera.width(), h = scene.camera.height();
    std::vector<bool> out(size_t(w) * h, all);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int j = 0; j <= 5; ++j)
                for (int i = 0; i <= 5; ++i) {
                    Ray ray = scene.camera.generateRay(
                        Vec2(x + std::min(i / 5.0f, 0.99999f), y + std::min(j / 5.0f, 0.99999f)));
                    SurfacePoint sp;
                    const bool hit = scene.intersect(ray, sp);
                    if (pred(hit, sp) != all) out[size_t(y) * w + x] = !all;
                }
    return out;
}

// The radiance the camera sees along `ray` through specular surfaces alone, a test's own trace
// (an oracle independent of the lessons' walks): the framework's sampleBSDF in radiance transport
// with the numbers (u, u), u; at a lamp its emitted radiance, at a miss the background, at the
// first non-specular surface (or after maxDepth bounces) black. `hitsLamp`: it ended on a lamp.
inline Color specularOracle(const Scene& scene, Ray ray, float u, int maxDepth, bool& hitsLamp) {
    Color beta(1.0f);
    hitsLamp = false;
    for (int bounces = 0; bounces <= maxDepth; ++bounces) {
        SurfacePoint sp;
        if (!scene.intersect(ray, sp)) return beta * scene.backgroundRadiance();
        if (sp.light >= 0) {
            hitsLamp = true;
            return beta * emittedRadiance(scene.lights[size_t(sp.light)], sp.n, -ray.d);
        }
        const Material& m = scene.materials[size_t(sp.material)];
        if (!m.isDelta() || bounces == maxDepth) return Color(0.0f);
        BSDFSample s;
        if (!sampleBSDF(m, sp.n, -ray.d, Vec2(u, u), u, Transport::Radiance, s)) return Color(0.0f);
        beta *= s.weight;
        ray = scene.spawnRay(sp, s.wi);
    }
    return Color(0.0f);
}

}  // namespace ps::testrender
