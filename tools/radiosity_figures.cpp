// radiosity_figures: lesson 11's radiosity figures (scripts/figures.sh runs it;
// lessons/11-classics/README.md shows them), and the path-traced patch averages its
// graded test compares with.
//
//   radiosity_figures OUTDIR [--quick] [--scenes DIR] [--patches FILE]
//       radiosity-shots.png          the Cornell box by radiosity (8 x 8 elements a quad) after 1,
//                                    10, 100 and 1000 shots and converged, and path traced (pt)
//       radiosity-ambient-shots.png  the same shots shown with the ambient term (Eq. 11.29)
//       radiosity-elements.png       converged with 2 x 2, 4 x 4, 8 x 8 and 16 x 16 elements a quad
//       radiosity-elements.md, .svg  the patch averages' error against pt's (FILE, default
//                                    tests/11-classics/data/cornell-patches.txt) for 1 ... 16
//                                    elements along a quad's edge: the discretisation bias
//   radiosity_figures --make-patches FILE [--samples N] [--scenes DIR]
//       writes FILE: pt's patch averages of the Cornell box (N points a quad, default 2^20, at
//       most 1000 bounces; Russian roulette ends the paths), with their standard errors.
// The pieces are lesson 11's (the reference, or yours with -DPATHSPACE_STUDENT=11).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include "03-path-tracing/pathtracer.h"
#include "11-classics/radiosity.h"
#include "image.h"
#include "render.h"
#include "scene_loader.h"

#ifndef PATHSPACE_SOURCE_DIR
#define PATHSPACE_SOURCE_DIR "."
#endif

using namespace ps;

namespace {

struct Settings {
    std::string out, scenes = PATHSPACE_SOURCE_DIR "/scenes";
    std::string patches = PATHSPACE_SOURCE_DIR "/tests/11-classics/data/cornell-patches.txt";
    std::string makePatches;
    int resolution = 256, ptSpp = 256, samples = 1 << 20, maxElements = 16, shotElements = 8;
    bool quick = false;
};

Scene cornell(const Settings& s) {
    const std::string path = s.scenes + "/cornell-box.scene";
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::stringstream buf;
    buf << in.rdbuf();
    std::string text = buf.str();
    const std::string from = "resolution 256 256";
    const size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error(path + ": no '" + from + "' to replace");
    text.replace(at, from.size(), "resolution " + std::to_string(s.resolution) + " " + std::to_string(s.resolution));
    return parseScene(text, path);
}

// Panels side by side, 4 black pixels between them.
Image sideBySide(const std::vector<Image>& panels) {
    const int gap = 4, h = panels[0].height;
    int w = -gap;
    for (const Image& p : panels) w += p.width + gap;
    Image out(w, h);
    int x0 = 0;
    for (const Image& p : panels) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < p.width; ++x) out.at(x0 + x, y) = p.at(x, y);
        x0 += p.width + gap;
    }
    return out;
}

void write(const Settings& s, const std::string& name, const Image& img) {
    const std::string path = s.out + "/" + name;
    writePNG(path, img, 0.0f);
    std::printf("radiosity_figures: wrote %s\n", path.c_str());
}

// The image of a radiosity integrator's current solution (one iteration without shots).
Image picture(const Scene& scene, RadiosityIntegrator& rad) {
    Scene still = scene;
    RadiositySettings none = radiositySettings(still.settings);
    none.shots = 0;
    setRadiositySettings(still.settings, none);
    Image img(scene.camera.width(), scene.camera.height());
    SampleStats stats;
    rad.renderIteration(still, 0, 1, img, stats);
    return img;
}

std::vector<PatchEstimate> readPatches(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path + " (make it with --make-patches)");
    std::vector<PatchEstimate> out;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream ls(line);
        int q, l;
        PatchEstimate e;
        ls >> q >> l >> e.mean.r >> e.mean.g >> e.mean.b >> e.stdError.r >> e.stdError.g >> e.stdError.b;
        if (!ls) throw std::runtime_error(path + ": malformed line '" + line + "'");
        out.push_back(e);
    }
    return out;
}

int makePatches(const Settings& s) {
    Settings one = s;
    one.resolution = 1;
    const Scene scene = cornell(one);
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<PatchEstimate> pt = patchRadiancePT(scene, s.samples, 1000, 11);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::ofstream f(s.makePatches);
    if (!f) throw std::runtime_error("cannot write " + s.makePatches);
    f << "# The Cornell box's patch averages by lesson 3's path tracer (patchRadiancePT, radiosity.h):\n"
         "# the mean radiance leaving each quad of scenes/cornell-box.scene, in file order, from "
      << s.samples
      << " points a quad,\n"
         "# at most 1000 bounces (Russian roulette ends the paths), seed 11. Made by\n"
         "#   ./build/radiosity_figures --make-patches tests/11-classics/data/cornell-patches.txt\n"
         "# ("
      << sec
      << " s). Columns: quad index, its scene file line, mean radiance r g b, standard error of the mean r g b.\n";
    char buf[512];
    for (size_t q = 0; q < pt.size(); ++q) {
        std::snprintf(buf, sizeof buf, "%zu %d  %.9g %.9g %.9g  %.6g %.6g %.6g\n", q, scene.quads[q].line, pt[q].mean.r,
                      pt[q].mean.g, pt[q].mean.b, pt[q].stdError.r, pt[q].stdError.g, pt[q].stdError.b);
        f << buf;
    }
    std::printf("radiosity_figures: wrote %s (%.1f s)\n", s.makePatches.c_str(), sec);
    return 0;
}

struct ErrorRow {
    int n = 0, elements = 0, shots = 0, worst = -1;
    double seconds = 0.0, meanRel = 0.0, maxRel = 0.0;
};

// The relative error of radiosity's patch averages against pt's, over the reflecting quads and
// the channels (as the graded test: the lamp's own patch is exactly its Le in both).
void compare(const Scene& scene, const std::vector<Color>& rad, const std::vector<PatchEstimate>& pt, ErrorRow& row) {
    double sum = 0.0;
    int count = 0;
    for (size_t q = 0; q < pt.size() && q < rad.size(); ++q)
        for (int c = 0; c < 3; ++c) {
            if (scene.prims[scene.quads[q].prim].light >= 0) continue;
            if (!(pt[q].mean[c] > 0.0)) continue;
            const double rel = std::abs(double(rad[q][c]) / pt[q].mean[c] - 1.0);
            sum += rel;
            if (rel > row.maxRel) row.worst = int(q);
            row.maxRel = std::max(row.maxRel, rel);
            ++count;
        }
    row.meanRel = count ? sum / count : 0.0;
}

void writeSvg(const std::string& path, const std::vector<ErrorRow>& rows) {
    std::ofstream f(path);
    const double W = 480, H = 320, L = 60, R = 20, T = 20, B = 50;
    const double x0 = std::log2(1.0), x1 = std::log2(double(rows.back().n));
    double lo = 1e9, hi = 0;
    for (const ErrorRow& r : rows) {
        lo = std::min(lo, r.meanRel);
        hi = std::max(hi, r.maxRel);
    }
    const double y0 = std::floor(std::log10(lo)), y1 = std::ceil(std::log10(hi));
    auto X = [&](double n) { return L + (std::log2(n) - x0) / std::max(1e-9, x1 - x0) * (W - L - R); };
    auto Y = [&](double e) { return T + (y1 - std::log10(e)) / std::max(1e-9, y1 - y0) * (H - T - B); };
    f << "<svg xmlns='http://www.w3.org/2000/svg' width='" << W << "' height='" << H
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n";
    f << "<line x1='" << L << "' y1='" << H - B << "' x2='" << W - R << "' y2='" << H - B << "' stroke='black'/>\n";
    f << "<line x1='" << L << "' y1='" << T << "' x2='" << L << "' y2='" << H - B << "' stroke='black'/>\n";
    for (const ErrorRow& r : rows)
        f << "<text x='" << X(r.n) << "' y='" << H - B + 16 << "' text-anchor='middle'>" << r.n << "</text>\n";
    for (double e = y0; e <= y1; e += 1.0)
        f << "<text x='" << L - 6 << "' y='" << Y(std::pow(10.0, e)) + 4 << "' text-anchor='end'>1e" << int(e)
          << "</text>\n";
    f << "<text x='" << (L + W - R) / 2 << "' y='" << H - 12
      << "' text-anchor='middle'>elements along a quad's edge (n x n a quad)</text>\n";
    const char* colors[2] = {"#1f77b4", "#d62728"};
    for (int k = 0; k < 2; ++k) {
        f << "<polyline fill='none' stroke='" << colors[k] << "' stroke-width='2' points='";
        for (const ErrorRow& r : rows) f << X(r.n) << "," << Y(k == 0 ? r.meanRel : r.maxRel) << " ";
        f << "'/>\n";
    }
    // A slope -1 guide (error proportional to the element size) from the first mean.
    f << "<line x1='" << X(rows.front().n) << "' y1='" << Y(rows.front().meanRel) << "' x2='" << X(rows.back().n)
      << "' y2='" << Y(rows.front().meanRel * rows.front().n / rows.back().n)
      << "' stroke='gray' stroke-dasharray='4 3'/>\n";
    f << "<text x='" << W - R - 4 << "' y='" << T + 12 << "' text-anchor='end' fill='" << colors[1]
      << "'>largest relative error of a patch</text>\n";
    f << "<text x='" << W - R - 4 << "' y='" << T + 28 << "' text-anchor='end' fill='" << colors[0]
      << "'>mean relative error over the patches</text>\n";
    f << "<text x='" << W - R - 4 << "' y='" << T + 44
      << "' text-anchor='end' fill='gray'>slope -1 (error ~ element size)</text>\n</svg>\n";
}

int figures(const Settings& s) {
    std::filesystem::create_directories(s.out);
    const Scene scene = cornell(s);
    // The shots: 1, 10, 100, 1000 and converged, flat and with the ambient term.
    {
        Scene fine = scene;
        RadiositySettings elements;
        elements.nu = elements.nv = s.shotElements;
        setRadiositySettings(fine.settings, elements);
        RadiosityIntegrator flat(false), ambient(true);
        checkRadiosityScene(fine);
        flat.prepare(fine);
        ambient.prepare(fine);
        std::vector<Image> a, b;
        SampleStats stats;
        int done = 0;
        for (int shots : {1, 10, 100, 1000, 1 << 30}) {
            flat.shootSteps(fine, shots - done, 7, stats);
            ambient.shootSteps(fine, shots - done, 7, stats);
            done = shots;
            a.push_back(picture(fine, flat));
            b.push_back(picture(fine, ambient));
            std::printf("radiosity_figures: %d shots (unshot %.3g of the emitted power)\n", flat.solution().shots,
                        unshotFraction(flat.mesh(), flat.solution()));
        }
        std::unique_ptr<Integrator> pt = makeIntegrator("pt");
        RenderOptions opt;
        opt.spp = s.ptSpp;
        opt.seed = 5;
        Scene deep = scene;
        deep.settings.maxDepth = 1000;
        a.push_back(render(deep, *pt, opt).film.mean());
        write(s, "radiosity-shots.png", sideBySide(a));
        write(s, "radiosity-ambient-shots.png", sideBySide(b));
    }
    // Element sizes: the images, and the patch averages against pt's.
    const std::vector<PatchEstimate> pt = readPatches(s.patches);
    std::vector<ErrorRow> rows;
    std::vector<Image> images;
    for (int n = 1; n <= s.maxElements; n *= 2) {
        Scene sc = scene;
        RadiositySettings elements;
        elements.nu = elements.nv = n;
        setRadiositySettings(sc.settings, elements);
        RadiosityIntegrator rad;
        const auto t0 = std::chrono::steady_clock::now();
        rad.prepare(sc);
        SampleStats stats;
        rad.shootSteps(sc, 1 << 30, 7, stats);
        ErrorRow row;
        row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        row.n = n;
        row.elements = rad.mesh().size();
        row.shots = rad.solution().shots;
        compare(sc, patchRadiance(rad.mesh(), rad.solution()), pt, row);
        rows.push_back(row);
        if (n >= 2) images.push_back(picture(sc, rad));
        std::printf("radiosity_figures: %d x %d elements: mean relative error %.4f, largest %.4f (quad %d) (%.1f s)\n",
                    n, n, row.meanRel, row.maxRel, row.worst, row.seconds);
        if (std::getenv("RADIOSITY_FIGURES_VERBOSE")) {
            const std::vector<Color> L = patchRadiance(rad.mesh(), rad.solution());
            for (size_t q = 0; q < pt.size(); ++q)
                std::printf("  quad %2zu: radiosity %.5f %.5f %.5f  pt %.5f %.5f %.5f\n", q, L[q].r, L[q].g, L[q].b,
                            pt[q].mean.r, pt[q].mean.g, pt[q].mean.b);
        }
    }
    write(s, "radiosity-elements.png", sideBySide(images));
    const std::string md = s.out + "/radiosity-elements.md";
    std::ofstream f(md);
    f << "| elements a quad | elements | shots | seconds | mean relative error | largest relative error |\n"
         "|---|---|---|---|---|---|\n";
    char buf[256];
    for (const ErrorRow& r : rows) {
        std::snprintf(buf, sizeof buf, "| %d x %d | %d | %d | %.2f | %.4f | %.4f |\n", r.n, r.n, r.elements, r.shots,
                      r.seconds, r.meanRel, r.maxRel);
        f << buf;
    }
    std::printf("radiosity_figures: wrote %s\n", md.c_str());
    writeSvg(s.out + "/radiosity-elements.svg", rows);
    std::printf("radiosity_figures: wrote %s/radiosity-elements.svg\n", s.out.c_str());
    return 0;
}

const char* kUsage =
    "usage: radiosity_figures OUTDIR [--quick] [--scenes DIR] [--patches FILE]\n"
    "       radiosity_figures --make-patches FILE [--samples N] [--scenes DIR]\n"
    "Writes lesson 11's radiosity figures (radiosity-shots, radiosity-ambient-shots, radiosity-elements .png,\n"
    "radiosity-elements .md and .svg) into OUTDIR, or pt's patch averages of the Cornell box into FILE.\n"
    "--quick: 64 x 64 pixels, pt at 2 spp, the shots with 2 x 2 elements, elements up to 4 x 4.\n";

}  // namespace

int main(int argc, char** argv) {
    Settings s;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool more = i + 1 < argc;
        if (a == "--quick") {
            s.quick = true;
            s.resolution = 64;
            s.ptSpp = 2;
            s.maxElements = 4;
            s.shotElements = 2;
        } else if (a == "--scenes" && more) {
            s.scenes = argv[++i];
        } else if (a == "--patches" && more) {
            s.patches = argv[++i];
        } else if (a == "--make-patches" && more) {
            s.makePatches = argv[++i];
        } else if (a == "--samples" && more) {
            s.samples = std::atoi(argv[++i]);
        } else if (a == "--help" || a == "-h" || a.rfind("-", 0) == 0 || !s.out.empty()) {
            std::fprintf(a == "--help" || a == "-h" ? stdout : stderr, "%s", kUsage);
            return a == "--help" || a == "-h" ? 0 : 2;
        } else {
            s.out = a;
        }
    }
    if (s.out.empty() == s.makePatches.empty() || s.samples < 2) {
        std::fprintf(stderr, "%s", kUsage);
        return 2;
    }
    try {
        return s.makePatches.empty() ? figures(s) : makePatches(s);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "radiosity_figures: error: %s\n", e.what());
        return 1;
    }
}
