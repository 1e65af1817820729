// The progressive render loop: iterations until a sample count or a time budget, optional
// error-against-run-time log against a reference image, progress bar, summary.
#pragma once
#include <functional>
#include <iosfwd>
#include <string>
#include "film.h"
#include "integrator.h"
#include "stopwatch.h"

namespace ps {

struct RenderOptions {
    int spp = 0;                        // iterations to run (0: none, unless a time budget is given)
    double seconds = 0.0;               // time budget (0: none); the loop stops at whichever comes first
    TimeClock clock = TimeClock::Wall;  // the clock of the budget and of every time reported
    uint64_t seed = 0;
    int threads = 0;                   // 0: all cores
    bool progress = false;             // draw a progress bar on stderr
    const Image* reference = nullptr;  // with a reference, one CSV row per iteration
    std::ostream* csv = nullptr;
    // Called after iterations 1, 2, 4, 8, ... and after the last one, with the number of
    // iterations so far, the render time so far and the film (not counted as render time).
    std::function<void(int spp, double seconds, const Film& film, const SampleStats& stats)> checkpoint;
};

struct RenderResult {
    Film film;
    int iterations = 0;
    double seconds = 0.0;               // time of preprocessing and iterations, without I/O and metrics
    TimeClock clock = TimeClock::Wall;  // the clock of seconds (RenderOptions::clock)
    SampleStats stats;
};

// CSV header of the error log: one row per iteration.
extern const char* const kErrorCsvHeader;

// Throws InputError when the scene's camera has a camera model and the integrator cannot render
// one (IntegratorCaps::cameraModels), naming those that can.
void checkCamera(const Scene& scene, const Integrator& integrator);
// The integrator's own check of the scene (IntegratorCaps::checkScene), then checkCamera: whether
// it can render the scene at all. render() calls it first; commands call it before they print.
void checkScene(const Scene& scene, const Integrator& integrator);

RenderResult render(const Scene& scene, Integrator& integrator, const RenderOptions& opt);

// "16 spp in 1.23 s (4.5 Mrays/s), 0 NaN, 0 Inf samples"; on the CPU clock "in 2.40 CPU s (2.3
// Mrays per CPU s)"
std::string summaryLine(const RenderResult& r);

}  // namespace ps
