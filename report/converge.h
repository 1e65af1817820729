// Error against run time for several algorithms on one scene (../shared/notes/testing.md):
// each algorithm renders for the same time budget, checkpoints at 1, 2, 4, ... iterations
// record wall time and the error against a reference, and the report is a CSV, a log-log SVG
// plot of relMSE against seconds with a slope -1 guide, a Markdown efficiency table, and the
// equal-time images side by side. Optionally (--regions) the error of each region of the
// image: the pixels that see a given material. The `converge` command's module
// (app/commands/converge.cpp), also used by the figure tools and benchmarks; not part of the renderer.
//
// A point light seen directly through the pinhole is a finite measurement (W_e I / d^2 lands in
// one pixel): light tracing and BPT draw that pixel, a path tracer cannot (both ends of the path
// are delta positions, no camera technique reaches it). Every comparison leaves such pixels out
// of every algorithm's error (MSE, relMSE, trimmed relMSE, regions) and says so.
#pragma once
#include <string>
#include <vector>
#include "metrics.h"
#include "render.h"

namespace ps {

// Pixels grouped into named regions, for the error of each region (`converge --regions`):
// region k holds the pixels whose centre ray first hits a surface of material names[k].
struct Regions {
    std::vector<std::string> names;
    std::vector<int> ofPixel;  // per pixel, row by row: its region, -1 for none
};

// Throws InputError for a material the scene does not have (the message lists those it has).
Regions materialRegions(const Scene& scene, const std::vector<std::string>& materials);
// relMSE (eps = 0.01) over the pixels of each region (0 for a region without pixels), without
// the pixels marked in leftOut (per pixel, row by row; empty: none).
std::vector<double> regionRelMse(const Image& img, const Image& ref, const Regions& regions,
                                 const std::vector<bool>& leftOut = {});

// A pixel in which point light `light` (its index among the scene's point lights, in file order)
// is seen directly: it projects inside the image and nothing lies between it and the pinhole.
struct PointLightPixel {
    int x = 0, y = 0;
    int light = 0;
};
std::vector<PointLightPixel> pointLightsInView(const Scene& scene);
// "pixel (x, y) sees point light N directly: a path tracer cannot sample that path (both ends
// delta positions); left out of the error of every algorithm"
std::string describe(const PointLightPixel& p);
// Per pixel, row by row: true for the pixels above (empty if there are none).
std::vector<bool> leftOutMask(const Scene& scene, const std::vector<PointLightPixel>& pixels);

struct ConvergeOptions {
    std::vector<std::string> algos;
    double seconds = 1.0;  // time budget of each algorithm and seed (0: none)
    int spp = 0;           // samples per pixel of each run (0: none); with both, whichever first
    Regions regions;       // empty: no per-region errors
    int seeds = 1;         // independent runs per algorithm (seeds 0 .. seeds-1), averaged
    int threads = 0;
    TimeClock clock = TimeClock::Wall;  // the clock of `seconds` and of every time reported
    bool progress = false;
    // Algorithm options (integrator.h, e.g. --paths EXPR) every algorithm is made with
    // (makeIntegrator(algo, options)); empty: none.
    AlgorithmOptions options;
};

struct ConvergencePoint {
    std::string algo;
    uint64_t seed = 0;
    int spp = 0;
    double seconds = 0.0;
    ErrorMetrics error;
    std::vector<double> regionRelMse;  // per region of ConvergeOptions::regions
    uint64_t nan = 0, inf = 0;
};

struct ConvergenceReport {
    std::vector<ConvergencePoint> points;  // in the order they were taken
    std::vector<Image> finalImages;        // per algorithm, seed 0, at the end of the budget
    double referenceVariance = 0.0;        // mean variance of the reference's pixels (0 if unknown)
    std::vector<PointLightPixel> leftOut;  // pixels left out of every error (pointLightsInView)
    TimeClock clock = TimeClock::Wall;     // the clock of every point's seconds
};

ConvergenceReport runConvergence(const Scene& scene, const Image& reference, const ConvergeOptions& opt);

// "scene,algorithm,seed,spp,seconds,mse,relmse,relmse_trim,nan,inf" and one row per point,
// after one line "# describe(pixel)" per pixel left out of the errors, if any.
std::string convergenceCsv(const std::string& sceneName, const ConvergenceReport& report);
// Log-log plot of relMSE (eps = 0.01) against seconds, the mean over seeds per algorithm.
std::string convergencePlotSvg(const std::string& title, const ConvergenceReport& report);
// Efficiency 1 / (relMSE x seconds) at the end of the budget, best first.
std::string efficiencyTable(const ConvergenceReport& report);
// relMSE of each region at the end of the run, the mean over seeds: one row per algorithm, one
// column per region, then the whole image.
std::string regionTable(const ConvergenceReport& report, const Regions& regions);
// Images next to each other, left to right, in the given order.
Image sideBySide(const std::vector<Image>& images);

}  // namespace ps
