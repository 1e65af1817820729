#include "render.h"
#include <omp.h>
#include <cstdio>
#include <ostream>
#include <sstream>
#include "errors.h"
#include "metrics.h"

namespace ps {

const char* const kErrorCsvHeader = "iteration,spp,seconds,mse,relmse,relmse_trim,nan,inf";

namespace {

void drawProgress(int done, int total, double seconds, double budget) {
    const double frac = total > 0 ? double(done) / total : (budget > 0 ? std::min(1.0, seconds / budget) : 0.0);
    const int width = 30, filled = static_cast<int>(frac * width);
    std::fprintf(stderr, "\r[%.*s%.*s] %3d%%  %d spp  %.1f s ", filled, "##############################",
                 width - filled, "..............................", static_cast<int>(frac * 100.0), done, seconds);
    std::fflush(stderr);
}

}  // namespace

void checkCamera(const Scene& scene, const Integrator& integrator) {
    const Camera& camera = scene.camera;
    if (camera.isPinhole() || integrator.caps.cameraModels) return;
    const std::string algo = integrator.name.empty() ? "this algorithm" : "'" + integrator.name + "'";
    std::string can;
    for (const IntegratorInfo& info : integratorList())
        if (info.caps.cameraModels) can += (can.empty() ? "" : ", ") + info.name;
    throw InputError(scene.path, camera.line,
                     "the camera has a camera model (" + camera.model()->describe() + "), which " + algo +
                         " cannot render (it assumes a pinhole camera); these can: " + can);
}

void checkScene(const Scene& scene, const Integrator& integrator) {
    if (integrator.caps.checkScene) integrator.caps.checkScene(scene);
    checkCamera(scene, integrator);
}

RenderResult render(const Scene& scene, Integrator& integrator, const RenderOptions& opt) {
    checkScene(scene, integrator);
    if (opt.threads > 0) omp_set_num_threads(opt.threads);
        // Rays traced before this render (by any thread) are not this render's: discard their count.
#pragma omp parallel
    takeRayCount();
    RenderResult res;
    res.film = Film(scene.camera.width(), scene.camera.height());
    if (opt.csv && opt.reference) *opt.csv << kErrorCsvHeader << "\n";

    double elapsed = 0.0, lastDraw = -1.0;
    int lastCheckpoint = 0;
    double t0 = clockSeconds(opt.clock);
    integrator.prepare(scene);
    elapsed += clockSeconds(opt.clock) - t0;

    Image iterImage(res.film.width(), res.film.height());
    for (int it = 0;; ++it) {
        if (opt.spp > 0 && it >= opt.spp) break;
        if (opt.seconds > 0.0 && elapsed >= opt.seconds) break;
        if (opt.spp <= 0 && opt.seconds <= 0.0) break;
        integrator.setDeadline(opt.seconds > 0.0 ? opt.seconds - elapsed : 0.0, opt.clock);  // none without --time
        integrator.setIterationsLeft(opt.spp > 0 ? opt.spp - it : -1);
        t0 = clockSeconds(opt.clock);
        std::fill(iterImage.pixels.begin(), iterImage.pixels.end(), Color(0.0f));
        integrator.renderIteration(scene, static_cast<uint32_t>(it), opt.seed, iterImage, res.stats);
        if (integrator.caps.latestIterationIsImage) res.film = Film(res.film.width(), res.film.height());
        res.film.addIteration(iterImage);
        elapsed += clockSeconds(opt.clock) - t0;
        res.iterations = it + 1;

        // Metrics and the progress bar are not counted as render time.
        if (opt.csv && opt.reference) {
            const ErrorMetrics e = computeError(res.film.mean(), *opt.reference);
            char line[256];
            std::snprintf(line, sizeof line, "%d,%d,%.6f,%.9g,%.9g,%.9g,%llu,%llu", it, it + 1, elapsed, e.mse,
                          e.relMse, e.relMseTrimmed, static_cast<unsigned long long>(res.stats.nan),
                          static_cast<unsigned long long>(res.stats.inf));
            *opt.csv << line << "\n";
        }
        if (opt.checkpoint && ((it + 1) & it) == 0) {  // it + 1 is a power of two
            opt.checkpoint(it + 1, elapsed, res.film, res.stats);
            lastCheckpoint = it + 1;
        }
        if (opt.progress && (elapsed - lastDraw > 0.1)) {
            drawProgress(it + 1, opt.spp, elapsed, opt.seconds);
            lastDraw = elapsed;
        }
    }
    if (opt.checkpoint && res.iterations > lastCheckpoint) opt.checkpoint(res.iterations, elapsed, res.film, res.stats);
    if (opt.progress) {
        drawProgress(res.iterations, opt.spp > 0 ? opt.spp : res.iterations, elapsed, opt.seconds);
        std::fprintf(stderr, "\n");
    }
    res.seconds = elapsed;
    res.clock = opt.clock;
    return res;
}

std::string summaryLine(const RenderResult& r) {
    char buf[256];
    const bool cpu = r.clock == TimeClock::Cpu;
    std::snprintf(buf, sizeof buf, "%d spp in %.2f %s (%.2f Mrays%s), %llu NaN, %llu Inf samples", r.iterations,
                  r.seconds, cpu ? "CPU s" : "s", r.seconds > 0 ? double(r.stats.rays) / r.seconds * 1e-6 : 0.0,
                  cpu ? " per CPU s" : "/s", static_cast<unsigned long long>(r.stats.nan),
                  static_cast<unsigned long long>(r.stats.inf));
    return buf;
}

}  // namespace ps
