// Lesson 11 — the integrators "radiosity" and "radiosity-ambient" (plumbing: read it, nothing to
// write here): the rows of form factors (formFactor, in the framework's task loop), the
// shooting loop (chooseShooter, shoot) and the image of the solution.
//
//   prepare        the elements (ElementMesh: every quad cut into the render parameter
//                  `elements`, radiositySettings), and
//                  the solution before the first shot (startRadiosity, Eq. 11.27)
//   iteration k    `shots` shooting steps (Eq. 11.28), fewer once the unshot power
//                  is below kStopResidual of the emitted power; then the image: each pixel the
//                  mean of kRadiosityPixelSamples^2 camera rays at fixed positions, each showing
//                  the radiance B / pi of the element it hits first (Eq. 11.20), flat; with
//                  "radiosity-ambient" plus rho ambient / pi (Eq. 11.29). The film keeps only
//                  the latest image (Integrator::latestIterationIsImage).
//
// Row i of the form factors is computed the first time element i shoots and kept (up to
// kKeptFloats numbers in all; beyond that it is computed again, with the same numbers: F_ij
// draws from taskRng(seed, i, j) only). So the solution, and the image, are the same for any
// number of threads.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <sstream>
#include "11-classics/radiosity.h"
#include "tasks.h"
#include "warps.h"

namespace ps {

namespace {
[[maybe_unused]] const bool elementsRegistered = Registry<RenderParameter>::add(
    "elements", {"radiosity: every quad cut into N x M elements, along its edges 1-2 and 1-4 (default 8 8)", "N M", 2,
                 [](const std::vector<float>& v) {
                     for (float x : v)
                         if (!(x >= 1.0f && x <= float(kMaxElements) && x == std::floor(x)))
                             return "must be whole numbers from 1 to " + std::to_string(kMaxElements) +
                                    " along each edge of a quad";
                     return std::string();
                 }});
[[maybe_unused]] const bool shotsRegistered = Registry<RenderParameter>::add(
    "shots", {"radiosity: shooting steps per iteration (default 256)", "S", 1, [](const std::vector<float>& v) {
                  return v[0] >= 1.0f && v[0] <= 1e9f && v[0] == std::floor(v[0])
                             ? std::string()
                             : std::string("must be a whole number of steps from 1 to 1e9");
              }});
constexpr uint64_t kRowSalt = 0x726164696f736974ull;   // "radiosit"
constexpr uint64_t kBackSalt = 0x6261636b2d6c6f73ull;  // "back-los"
constexpr size_t kKeptFloats = size_t(1) << 26;        // 256 MB of rows at most

// Whether every corner of element b lies on or behind the plane of element a's front.
bool behind(const Element& b, const Element& a) {
    const glm::dvec3 n(a.normal), o(a.corners[0]);
    for (const Vec3& c : b.corners)
        if (glm::dot(glm::dvec3(c) - o, n) > 0.0) return false;
    return true;
}
}  // namespace

FormFactorRow formFactorRow(const Scene& scene, const ElementMesh& mesh, int i, uint64_t seed, SampleStats& stats,
                            const Integrator* stop) {
    FormFactorRow row;
    row.F.assign(size_t(mesh.size()), 0.0f);
    const Element& ei = mesh[i];
    const int samples = formFactorSamples(mesh.size());
    std::atomic<bool> stopped{false};
    runTasks(TaskLoop(mesh.size(), seed, uint32_t(i)), stats, [&](int j, Rng& rng, Task&) {
        if (stopped.load(std::memory_order_relaxed)) return;
        if (stop && (j & 63) == 0 && stop->timeIsUp()) {  // a task is 64 elements: once per task
            stopped = true;
            return;
        }
        const Element& ej = mesh[j];
        if (ej.quad == ei.quad || behind(ej, ei) || behind(ei, ej)) return;
        row.F[size_t(j)] = formFactor(scene, mesh, i, j, samples, rng);
    });
    if (stopped) return {};
    // The power lost to the backs of reflecting quads: cosine rays from element i (Eq. 11.24:
    // the fraction of them that arrive somewhere is the form factor to there).
    Rng rng = taskRng(seed ^ kBackSalt, uint32_t(i), 0);
    const int rays = 4 * kFormFactorSamples;
    int back = 0;
    for (int k = 0; k < rays; ++k) {
        const SurfacePoint from = mesh.samplePoint(i, rng.uniform2());
        Ray probe = scene.spawnRay(from, Frame(from.n).toWorld(sampleCosineHemisphere(rng.uniform2())));
        SurfacePoint at;
        const bool reflectingBack = scene.intersect(probe, at) && glm::dot(at.n, probe.d) >= 0.0f &&
                                    !isBlack(scene.materials[size_t(at.material)].albedo);
        back += reflectingBack ? 1 : 0;
    }
    row.back = float(back) / float(rays);
    return row;
}

double unshotFraction(const ElementMesh& mesh, const RadiositySolution& s) {
    if (s.unshot.size() != size_t(mesh.size())) return 0.0;
    double unshot = 0.0, emitted = 0.0;
    for (int i = 0; i < mesh.size(); ++i) {
        const Color& u = s.unshot[size_t(i)];
        const Color& E = mesh[i].E;
        unshot += (double(u.r) + u.g + u.b) * mesh[i].area;
        emitted += (double(E.r) + E.g + E.b) * mesh[i].area;
    }
    return emitted > 0.0 ? unshot / emitted : 0.0;
}

RadiositySettings radiositySettings(const RenderSettings& settings) {
    RadiositySettings r;
    const std::vector<float> e = renderParameterValues(settings, "elements", {float(r.nu), float(r.nv)});
    r.nu = int(e[0]);
    r.nv = int(e[1]);
    r.shots = int(renderParameter(settings, "shots", float(r.shots)));
    return r;
}

void setRadiositySettings(RenderSettings& settings, const RadiositySettings& radiosity) {
    settings.parameters["elements"] = {float(radiosity.nu), float(radiosity.nv)};
    settings.parameters["shots"] = {float(radiosity.shots)};
}

void RadiosityIntegrator::prepare(const Scene& scene) {
    const RadiositySettings settings = radiositySettings(scene.settings);
    mesh_ = ElementMesh(scene, settings.nu, settings.nv);
    solution_ = startRadiosity(mesh_);
    rows_.assign(size_t(mesh_.size()), {});
    keptFloats_ = 0;
    rowsComputed_ = 0;
    cutIterations_ = 0;
    backPower_ = shotPower_ = 0.0;
    ambientTerm_ = Color(0.0f);
}

void RadiosityIntegrator::shootSteps(const Scene& scene, int shots, uint64_t seed, SampleStats& stats) {
    const size_t n = size_t(mesh_.size());
    if (solution_.B.size() != n || solution_.unshot.size() != n) return;  // not started (a TODO)
    const uint64_t rowSeed = mix64(seed ^ kRowSalt);
    for (int k = 0; k < shots; ++k) {
        if (unshotFraction(mesh_, solution_) < kStopResidual) break;
        if (timeIsUp()) {  // the render's budget (--time): the steps made so far are the image
            ++cutIterations_;
            break;
        }
        const int i = chooseShooter(mesh_, solution_);
        if (i < 0 || size_t(i) >= n) break;
        FormFactorRow computed;
        const FormFactorRow* row = nullptr;
        if (!rows_[size_t(i)].F.empty()) {
            row = &rows_[size_t(i)];
        } else {
            computed = formFactorRow(scene, mesh_, i, rowSeed, stats, this);
            if (computed.F.empty()) {  // abandoned at the time budget: no step
                ++cutIterations_;
                break;
            }
            ++rowsComputed_;
            row = &computed;
            if (keptFloats_ + n <= kKeptFloats) {
                keptFloats_ += n;
                rows_[size_t(i)] = computed;
                row = &rows_[size_t(i)];
            }
        }
        const Color& u = solution_.unshot[size_t(i)];
        const double power = (double(u.r) + u.g + u.b) * mesh_[i].area;
        shotPower_ += power;
        backPower_ += power * row->back;
        shoot(mesh_, solution_, i, row->F);
    }
}

Color RadiosityIntegrator::radiance(int element) const {
    if (element < 0 || size_t(element) >= solution_.B.size()) return Color(0.0f);
    Color B = solution_.B[size_t(element)];
    if (ambient_) B += mesh_[element].rho * ambientTerm_;
    return B / kPi;
}

void RadiosityIntegrator::renderIteration(const Scene& scene, uint32_t, uint64_t seed, Image& out, SampleStats& stats) {
    shootSteps(scene, radiositySettings(scene.settings).shots, seed, stats);
    if (ambient_ && solution_.unshot.size() == size_t(mesh_.size())) ambientTerm_ = ambientRadiosity(mesh_, solution_);
    constexpr int m = kRadiosityPixelSamples;
    renderPixelTasks(seed, 0, out, stats, false, [&](int pixel, Rng& rng, Task&) {
        Color sum(0.0f);
        for (int sy = 0; sy < m; ++sy)
            for (int sx = 0; sx < m; ++sx) {
                const Vec2 raster(float(pixel % out.width) + (float(sx) + 0.5f) / m,
                                  float(pixel / out.width) + (float(sy) + 0.5f) / m);
                Ray ray = cameraRay(scene.camera, raster, rng);  // a pinhole draws no number
                SurfacePoint hit;
                if (scene.intersect(ray, hit)) sum += radiance(mesh_.elementAt(hit, ray.d));
            }
        return sum / float(m * m);
    });
}

std::vector<std::string> RadiosityIntegrator::report() const {
    std::vector<std::string> lines;
    std::ostringstream s;
    s << mesh_.size() << " elements (" << mesh_.nu() << " x " << mesh_.nv() << " per quad), " << solution_.shots
      << " shots, " << rowsComputed_ << " rows of form factors computed (" << formFactorSamples(mesh_.size())
      << " samples each); unshot power " << unshotFraction(mesh_, solution_) << " of the emitted (stops below "
      << kStopResidual << ")";
    if (cutIterations_ > 0) s << "; " << cutIterations_ << " iteration(s) ended early at the time budget (--time)";
    lines.push_back(s.str());
    if (backPower_ > 0.0) {
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "warning: %.3g %% of the shot power arrived at the backs of reflecting quads, which "
                      "one-sided elements drop (pt reflects it): quads facing away from the light, or "
                      "elements that reach into a closed object (light leaks)",
                      100.0 * backPower_ / shotPower_);
        lines.push_back(buf);
    }
    return lines;
}

namespace {
struct RadiosityFlat : RadiosityIntegrator {
    RadiosityFlat() : RadiosityIntegrator(false) {}
};
struct RadiosityAmbient : RadiosityIntegrator {
    RadiosityAmbient() : RadiosityIntegrator(true) {}
};
}  // namespace

// Every iteration's image is the whole current solution; diffuse quads and area lights only; its
// camera rays come from the framework's cameraRay, through a camera model too (each iteration's
// image then has its m x m camera samples per pixel).
PS_REGISTER_INTEGRATOR_CAPS(
    RadiosityFlat, "radiosity",
    "progressive radiosity: diffuse quads, form factors by ray casting, shooting (lesson 11)",
    IntegratorCaps().withCameraModels().withLatestIterationIsImage().withSceneCheck(checkRadiosityScene));
PS_REGISTER_INTEGRATOR_CAPS(
    RadiosityAmbient, "radiosity-ambient",
    "progressive radiosity shown with the ambient term of Cohen et al. 1988 (lesson 11)",
    IntegratorCaps().withCameraModels().withLatestIterationIsImage().withSceneCheck(checkRadiosityScene));

}  // namespace ps
