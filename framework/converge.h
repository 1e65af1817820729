// Error against run time for several algorithms on one scene (../shared/notes/testing.md):
// each algorithm renders for the same time budget, checkpoints at 1, 2, 4, ... iterations
// record wall time and the error against a reference, and the report is a CSV, a log-log SVG
// plot of relMSE against seconds with a slope -1 guide, a Markdown efficiency table, and the
// equal-time images side by side.
#pragma once
#include <string>
#include <vector>
#include "metrics.h"
#include "render.h"

namespace ps {

struct ConvergeOptions {
    std::vector<std::string> algos;
    double seconds = 1.0;   // time budget of each algorithm and seed
    int seeds = 1;          // independent runs per algorithm (seeds 0 .. seeds-1), averaged
    int threads = 0;
    bool progress = false;
};

struct ConvergencePoint {
    std::string algo;
    uint64_t seed = 0;
    int spp = 0;
    double seconds = 0.0;
    ErrorMetrics error;
    uint64_t nan = 0, inf = 0;
};

struct ConvergenceReport {
    std::vector<ConvergencePoint> points;   // in the order they were taken
    std::vector<Image> finalImages;         // per algorithm, seed 0, at the end of the budget
    double referenceVariance = 0.0;         // mean variance of the reference's pixels (0 if unknown)
};

ConvergenceReport runConvergence(const Scene& scene, const Image& reference, const ConvergeOptions& opt);

// "scene,algorithm,seed,spp,seconds,mse,relmse,relmse_trim,nan,inf" and one row per point.
std::string convergenceCsv(const std::string& sceneName, const ConvergenceReport& report);
// Log-log plot of relMSE (eps = 0.01) against seconds, the mean over seeds per algorithm.
std::string convergencePlotSvg(const std::string& title, const ConvergenceReport& report);
// Efficiency 1 / (relMSE x seconds) at the end of the budget, best first.
std::string efficiencyTable(const ConvergenceReport& report);
// Images next to each other, left to right, in the given order.
Image sideBySide(const std::vector<Image>& images);

}  // namespace ps
