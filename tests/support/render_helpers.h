// Rendering in the graded tests, once for every lesson: a fixed-seed render of a named
// integrator through the framework's render loop, and the sums the tests compare.
#pragma once
#include <memory>
#include <string>
#include "film.h"
#include "image.h"
#include "integrator.h"
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

}  // namespace ps::testrender
