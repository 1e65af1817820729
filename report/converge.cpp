#include "converge.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include "errors.h"

namespace ps {

Regions materialRegions(const Scene& scene, const std::vector<std::string>& materials) {
    Regions r;
    r.names = materials;
    std::vector<int> regionOfMaterial(scene.materials.size(), -1);
    for (size_t k = 0; k < materials.size(); ++k) {
        size_t m = 0;
        while (m < scene.materials.size() && scene.materials[m].name != materials[k]) ++m;
        if (m == scene.materials.size()) {
            std::string known;
            for (const Material& mat : scene.materials)  // "(emitter)" and the like are not in the file
                if (mat.name.rfind('(', 0) != 0) known += (known.empty() ? "" : ", ") + mat.name;
            throw InputError("no material '" + materials[k] + "' for --regions (the scene has: " + known + ")");
        }
        regionOfMaterial[m] = static_cast<int>(k);
    }
    const int w = scene.camera.width(), h = scene.camera.height();
    r.ofPixel.assign(size_t(w) * h, -1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Ray ray = scene.camera.generateRay(Vec2(x + 0.5f, y + 0.5f));
            SurfacePoint sp;
            if (scene.intersect(ray, sp) && sp.material >= 0)
                r.ofPixel[size_t(y) * w + x] = regionOfMaterial[sp.material];
        }
    return r;
}

std::vector<double> regionRelMse(const Image& img, const Image& ref, const Regions& regions,
                                 const std::vector<bool>& leftOut) {
    std::vector<double> sum(regions.names.size(), 0.0), count(regions.names.size(), 0.0);
    for (size_t i = 0; i < img.pixels.size() && i < regions.ofPixel.size(); ++i) {
        const int k = regions.ofPixel[i];
        if (k < 0 || (i < leftOut.size() && leftOut[i])) continue;
        for (int c = 0; c < 3; ++c) {
            const double x = img.pixels[i][c], r = ref.pixels[i][c];
            sum[k] += (x - r) * (x - r) / (r * r + kRelMseEpsilon);
            count[k] += 1.0;
        }
    }
    for (size_t k = 0; k < sum.size(); ++k) sum[k] = count[k] > 0.0 ? sum[k] / count[k] : 0.0;
    return sum;
}

std::vector<PointLightPixel> pointLightsInView(const Scene& scene) {
    std::vector<PointLightPixel> out;
    const Camera& camera = scene.camera;
    int index = 0;
    for (const Light& light : scene.lights) {
        if (light.kind != LightKind::Point) continue;
        const int n = index++;
        Vec2 raster;
        if (!camera.rasterPosition(light.position, raster)) continue;  // behind or outside the image
        SurfacePoint at;  // not on a surface: no offset, no triangle to skip
        at.p = light.position;
        if (scene.occluded(scene.spawnRayTo(at, camera.position()))) continue;
        PointLightPixel p;
        p.x = std::min(static_cast<int>(std::floor(raster.x)), camera.width() - 1);
        p.y = std::min(static_cast<int>(std::floor(raster.y)), camera.height() - 1);
        p.light = n;
        out.push_back(p);
    }
    return out;
}

std::string describe(const PointLightPixel& p) {
    return "pixel (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ") sees point light " +
           std::to_string(p.light) +
           " directly: a path tracer cannot sample that path (both ends delta positions); left out of the error "
           "of every algorithm";
}

std::vector<bool> leftOutMask(const Scene& scene, const std::vector<PointLightPixel>& pixels) {
    if (pixels.empty()) return {};
    std::vector<bool> mask(size_t(scene.camera.width()) * scene.camera.height(), false);
    for (const PointLightPixel& p : pixels) mask[size_t(p.y) * scene.camera.width() + p.x] = true;
    return mask;
}

ConvergenceReport runConvergence(const Scene& scene, const Image& reference, const ConvergeOptions& opt) {
    ConvergenceReport report;
    report.leftOut = pointLightsInView(scene);
    report.clock = opt.clock;
    const std::vector<bool> leftOut = leftOutMask(scene, report.leftOut);
    for (const std::string& algo : opt.algos) {
        for (int seed = 0; seed < opt.seeds; ++seed) {
            auto integrator = makeIntegrator(algo, opt.options);
            RenderOptions ro;
            ro.seconds = opt.seconds;
            ro.clock = opt.clock;
            ro.spp = opt.spp;
            ro.seed = static_cast<uint64_t>(seed);
            ro.threads = opt.threads;
            ro.progress = opt.progress;
            ro.checkpoint = [&](int spp, double seconds, const Film& film, const SampleStats& stats) {
                ConvergencePoint p;
                p.algo = algo;
                p.seed = static_cast<uint64_t>(seed);
                p.spp = spp;
                p.seconds = seconds;
                const Image mean = film.mean();
                p.error = computeError(mean, reference, leftOut);
                if (!opt.regions.names.empty()) p.regionRelMse = regionRelMse(mean, reference, opt.regions, leftOut);
                p.nan = stats.nan;
                p.inf = stats.inf;
                report.points.push_back(p);
            };
            if (opt.progress) std::fprintf(stderr, "%s, seed %d\n", algo.c_str(), seed);
            const RenderResult r = render(scene, *integrator, ro);
            if (seed == 0) report.finalImages.push_back(r.film.mean());
        }
    }
    return report;
}

std::string convergenceCsv(const std::string& sceneName, const ConvergenceReport& report) {
    std::ostringstream os;
    for (const PointLightPixel& p : report.leftOut) os << "# " << describe(p) << "\n";
    os << "scene,algorithm,seed,spp,seconds,mse,relmse,relmse_trim,nan,inf\n";
    char line[512];
    for (const ConvergencePoint& p : report.points) {
        std::snprintf(line, sizeof line, "%s,%s,%llu,%d,%.6f,%.9g,%.9g,%.9g,%llu,%llu\n", sceneName.c_str(),
                      p.algo.c_str(), static_cast<unsigned long long>(p.seed), p.spp, p.seconds, p.error.mse,
                      p.error.relMse, p.error.relMseTrimmed, static_cast<unsigned long long>(p.nan),
                      static_cast<unsigned long long>(p.inf));
        os << line;
    }
    return os.str();
}

namespace {

// Per algorithm, in first-appearance order: the mean over seeds of (seconds, relMSE) at each
// checkpoint taken by every seed.
struct Curve {
    std::string algo;
    std::vector<double> seconds, relMse;
    ConvergencePoint last;  // seed-averaged final point (spp of seed 0)
};

std::vector<Curve> meanCurves(const ConvergenceReport& report) {
    std::vector<Curve> curves;
    std::map<std::string, std::map<int, std::vector<const ConvergencePoint*>>> byAlgo;
    std::map<std::string, std::map<uint64_t, const ConvergencePoint*>> lastOf;
    for (const ConvergencePoint& p : report.points) {
        if (!byAlgo.count(p.algo)) curves.push_back({p.algo, {}, {}, {}});
        byAlgo[p.algo][p.spp].push_back(&p);
        lastOf[p.algo][p.seed] = &p;
    }
    for (Curve& c : curves) {
        const size_t seeds = lastOf[c.algo].size();
        for (const auto& [spp, pts] : byAlgo[c.algo]) {
            if (pts.size() != seeds) continue;  // a checkpoint not every seed reached
            double s = 0, e = 0;
            for (const ConvergencePoint* p : pts) {
                s += p->seconds;
                e += p->error.relMse;
            }
            c.seconds.push_back(s / pts.size());
            c.relMse.push_back(e / pts.size());
        }
        ConvergencePoint& L = c.last;
        L.algo = c.algo;
        for (const auto& [seed, p] : lastOf[c.algo]) {
            if (seed == 0) L.spp = p->spp;
            L.seconds += p->seconds / seeds;
            L.error.mse += p->error.mse / seeds;
            L.error.relMse += p->error.relMse / seeds;
            L.error.relMseTrimmed += p->error.relMseTrimmed / seeds;
            L.regionRelMse.resize(p->regionRelMse.size(), 0.0);
            for (size_t k = 0; k < p->regionRelMse.size(); ++k) L.regionRelMse[k] += p->regionRelMse[k] / seeds;
            L.nan += p->nan;
            L.inf += p->inf;
        }
    }
    return curves;
}

}  // namespace

std::string convergencePlotSvg(const std::string& title, const ConvergenceReport& report) {
    const std::vector<Curve> curves = meanCurves(report);
    const double W = 720, H = 480, left = 80, right = 170, top = 40, bottom = 60;
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const Curve& c : curves)
        for (size_t i = 0; i < c.seconds.size(); ++i) {
            if (!(c.seconds[i] > 0.0) || !(c.relMse[i] > 0.0)) continue;
            x0 = std::min(x0, std::log10(c.seconds[i]));
            x1 = std::max(x1, std::log10(c.seconds[i]));
            y0 = std::min(y0, std::log10(c.relMse[i]));
            y1 = std::max(y1, std::log10(c.relMse[i]));
        }
    if (x0 > x1) {
        x0 = -3;
        x1 = 0;
        y0 = -3;
        y1 = 0;
    }
    x0 = std::floor(x0);
    x1 = std::max(std::ceil(x1), x0 + 1);  // whole decades
    y0 = std::floor(y0);
    y1 = std::max(std::ceil(y1), y0 + 1);
    auto X = [&](double lx) { return left + (lx - x0) / (x1 - x0) * (W - left - right); };
    auto Y = [&](double ly) { return H - bottom - (ly - y0) / (y1 - y0) * (H - top - bottom); };
    const char* colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

    std::ostringstream os;
    char buf[512];
    std::snprintf(
        buf, sizeof buf,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" font-family=\"sans-serif\" font-size=\"12\">\n"
        "<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
        W, H);
    os << buf;
    os << "<text x=\"" << left << "\" y=\"24\" font-size=\"14\">" << title << "</text>\n";
    // Decade grid and labels.
    for (double d = x0; d <= x1 + 1e-9; d += 1) {
        std::snprintf(buf, sizeof buf,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n"
                      "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">1e%d</text>\n",
                      X(d), Y(y0), X(d), Y(y1), X(d), H - bottom + 18, static_cast<int>(d));
        os << buf;
    }
    for (double d = y0; d <= y1 + 1e-9; d += 1) {
        std::snprintf(buf, sizeof buf,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n"
                      "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">1e%d</text>\n",
                      X(x0), Y(d), X(x1), Y(d), left - 6, Y(d) + 4, static_cast<int>(d));
        os << buf;
    }
    std::snprintf(
        buf, sizeof buf,
        "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n"
        "<text x=\"18\" y=\"%.1f\" text-anchor=\"middle\" transform=\"rotate(-90 18 %.1f)\">relMSE (eps = 0.01)</text>\n",
        (X(x0) + X(x1)) / 2, H - 20, clockUnit(report.clock), (Y(y0) + Y(y1)) / 2, (Y(y0) + Y(y1)) / 2);
    os << buf;
    // Slope -1 guide through the middle of the plot: error proportional to 1 / time.
    {
        const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2, h = std::min(x1 - x0, y1 - y0) / 2;
        std::snprintf(
            buf, sizeof buf,
            "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"#888\" stroke-dasharray=\"6 4\"/>\n"
            "<text x=\"%.1f\" y=\"%.1f\" fill=\"#888\">slope -1</text>\n",
            X(cx - h), Y(cy + h), X(cx + h), Y(cy - h), X(cx + h) + 4, Y(cy - h));
        os << buf;
    }
    for (size_t k = 0; k < curves.size(); ++k) {
        const Curve& c = curves[k];
        const char* col = colors[k % 8];
        os << "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" << col << "\" points=\"";
        for (size_t i = 0; i < c.seconds.size(); ++i)
            if (c.seconds[i] > 0.0 && c.relMse[i] > 0.0) {
                std::snprintf(buf, sizeof buf, "%.1f,%.1f ", X(std::log10(c.seconds[i])), Y(std::log10(c.relMse[i])));
                os << buf;
            }
        os << "\"/>\n";
        std::snprintf(buf, sizeof buf,
                      "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"2\"/>\n"
                      "<text x=\"%.1f\" y=\"%.1f\">%s</text>\n",
                      W - right + 14, top + 20 + 18.0 * k, W - right + 38, top + 20 + 18.0 * k, col, W - right + 44,
                      top + 24 + 18.0 * k, c.algo.c_str());
        os << buf;
    }
    os << "</svg>\n";
    return os.str();
}

std::string efficiencyTable(const ConvergenceReport& report) {
    std::vector<Curve> curves = meanCurves(report);
    auto efficiency = [](const ConvergencePoint& p) {
        return p.error.relMse > 0 && p.seconds > 0 ? 1.0 / (p.error.relMse * p.seconds) : 0.0;
    };
    std::sort(curves.begin(), curves.end(),
              [&](const Curve& a, const Curve& b) { return efficiency(a.last) > efficiency(b.last); });
    std::ostringstream os;
    os << "| algorithm | spp | " << (report.clock == TimeClock::Cpu ? "CPU seconds" : "seconds")
       << " | relMSE | relMSE without top 0.1 % | efficiency 1/(relMSE s) | NaN | Inf |\n"
          "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    char line[512];
    for (const Curve& c : curves) {
        const ConvergencePoint& p = c.last;
        std::snprintf(line, sizeof line, "| %s | %d | %.3f | %.4g | %.4g | %.4g | %llu | %llu |\n", p.algo.c_str(),
                      p.spp, p.seconds, p.error.relMse, p.error.relMseTrimmed, efficiency(p),
                      static_cast<unsigned long long>(p.nan), static_cast<unsigned long long>(p.inf));
        os << line;
    }
    return os.str();
}

std::string regionTable(const ConvergenceReport& report, const Regions& regions) {
    std::ostringstream os;
    os << "| algorithm | spp |";
    for (const std::string& n : regions.names) os << " " << n << " |";
    os << " whole image |\n|---|---:|";
    for (size_t k = 0; k <= regions.names.size(); ++k) os << "---:|";
    os << "\n";
    char cell[64];
    for (const Curve& c : meanCurves(report)) {
        os << "| " << c.algo << " | " << c.last.spp << " |";
        for (size_t k = 0; k < regions.names.size(); ++k) {
            std::snprintf(cell, sizeof cell, " %.4g |", k < c.last.regionRelMse.size() ? c.last.regionRelMse[k] : 0.0);
            os << cell;
        }
        std::snprintf(cell, sizeof cell, " %.4g |\n", c.last.error.relMse);
        os << cell;
    }
    return os.str();
}

Image sideBySide(const std::vector<Image>& images) {
    int w = 0, h = 0;
    for (const Image& im : images) {
        w += im.width;
        h = std::max(h, im.height);
    }
    Image out(w, h);
    int x0 = 0;
    for (const Image& im : images) {
        for (int y = 0; y < im.height; ++y)
            for (int x = 0; x < im.width; ++x) out.at(x0 + x, y) = im.at(x, y);
        x0 += im.width;
    }
    return out;
}

}  // namespace ps
