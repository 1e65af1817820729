// pathspace: the command-line front end.  `pathspace --help` lists the commands.
#include <unistd.h>
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>
#include <sys/stat.h>
#include "07-bidirectional/bpt.h"
#include "converge.h"
#include "errors.h"
#include "image.h"
#include "integrator.h"
#include "render.h"
#include "scene_loader.h"
#include "threads.h"

namespace {

const char* kUsage = R"(pathspace - a light transport course renderer

usage:
  pathspace render SCENE [options]   render a scene file (see scenes/README.md)
  pathspace converge SCENE --algos A,B,... (--time SECONDS | --spp N) [options]
                                     error against run time of several algorithms
  pathspace info SCENE               print what the scene contains and needs
  pathspace pyramid SCENE [options]  Veach's pyramid: the image of every bidirectional
                                     technique (s, t) alone, per path length (lesson 7)
  pathspace --help                   this text

render options:
  --algo NAME        integrator (default: the scene's 'render algo', else eyelight)
  --spp N            iterations (samples per pixel) to render (default: the scene's)
  --time SECONDS     stop after this much render time instead (with --spp: whichever first)
  --maxdepth D       maximum number of bounces, 0 = emission seen directly (default: the scene's)
  --seed S           random seed (default 0); the same seed gives the same image
  --threads T        worker threads (default: all cores); the image does not depend on it
  --out FILE         output image, .png, .pfm or .hdr (default: SCENE's name + .png);
                     a .pfm with the exact values is always written next to a .png or .hdr
  --variance FILE    also write the per-pixel variance of the mean as a .pfm
  --reference REF    a reference image (.pfm or .hdr): log error against run time
  --csv FILE         where that log goes (default: the output's name + .csv)
  --no-prune         do not leave out work the scene cannot use (integrators print what
                     they leave out; pruning is exact, this switch is there to check it)
  --progress / --no-progress   progress bar on stderr (default: when stderr is a terminal)

converge options:
  --algos A,B,...    the algorithms to compare (required)
  --time SECONDS     time budget of each algorithm (and seed)
  --spp N            samples per pixel of each algorithm (and seed): equal samples instead
                     of equal time (with --time too: whichever comes first); one is required
  --reference REF    the reference image (.pfm); without it one is rendered first with
                     --ref-algo (default: the first algorithm) for --ref-time seconds
                     (default: 10 x --time; required without --time) and written to
                     DIR/reference.pfm
  --regions M1,M2,...  also the relMSE of each region of the image: region Mk holds the pixels
                     whose centre ray first hits a surface of material Mk (a 'material' name
                     of the scene file); printed and written to DIR/regions.md
  --seeds K          independent runs per algorithm, averaged in the plot and table (default 1)
  --out DIR          where the report goes (default: converge-SCENE); it holds
                     convergence.csv, convergence.svg (log-log relMSE against seconds with a
                     slope -1 guide), efficiency.md, equal-time.png (the algorithms' images at
                     the end of the budget, left to right in --algos order, then the reference)
  --threads T, --maxdepth D, --no-prune, --progress/--no-progress   as for render

pyramid options:
  --max-length K     path lengths 1..K (K edges at most; default 4); row k of the pyramid holds
                     the techniques s = 0..k+1 (t = k+1-s) from left to right
  --spp N            samples per pixel (default: the scene's)
  --seed S, --threads T, --no-prune   as for render
  --exposure E       PNG exposure in stops (default 0)
  --out PREFIX       writes PREFIX-unweighted.png (each technique alone, its unweighted
                     estimate), PREFIX-weighted.png (the MIS-weighted ones: a row adds up
                     to the paths of that length), PREFIX-s-t.pfm and PREFIX-s-t-weighted.pfm
                     for each technique (default: SCENE's name + -pyramid); cells of techniques
                     that cannot sample the scene's paths stay black (listed on stdout)

exit status: 0 on success, 1 on bad input (the message names file, line and problem),
2 on a bad command line.
)";

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string stem(const std::string& path) {
    size_t slash = path.find_last_of('/');
    size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
    return path.substr(0, dot);
}
std::string baseName(const std::string& path) {
    size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

template <class T>
T parseNumber(const std::string& opt, const std::string& s) {
    T v{};
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size())
        throw UsageError("option " + opt + " needs a number, got '" + s + "'");
    return v;
}

// One line per piece of work the integrator leaves out on this scene (Integrator::leftOut).
void printLeftOut(const std::string& algo, const ps::Integrator& integrator, const ps::Scene& scene) {
    for (const std::string& line : integrator.leftOut(scene))
        std::cerr << "pathspace: " << algo << " leaves out " << line << "\n";
}

void listAlgorithms() {
    std::cerr << "algorithms:\n";
    for (const auto& i : ps::integratorList()) std::cerr << "  " << i.name << "  " << i.description << "\n";
}

int info(const std::vector<std::string>& args) {
    if (args.size() != 1) throw UsageError("'info' takes one scene file");
    const ps::Scene scene = ps::loadScene(args[0]);
    std::cout << args[0] << ": " << scene.camera.width() << "x" << scene.camera.height() << " pixels, "
              << scene.triangles.size() << " triangles, " << scene.spheres.size() << " spheres, "
              << scene.materials.size() << " materials, " << scene.lights.size() << " lights, BVH depth "
              << scene.bvh.depth() << "\n  " << scene.caps.describe() << "\n  defaults: spp "
              << scene.settings.spp << ", maxdepth " << scene.settings.maxDepth << ", algo " << scene.settings.algo
              << "\n";
    return 0;
}

int render(const std::vector<std::string>& args) {
    std::string scenePath, algo, out, reference, csvPath, variancePath;
    int spp = 0, threads = 0, maxDepth = -1;
    double seconds = 0.0;
    uint64_t seed = 0;
    bool progress = isatty(2), prune = true;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= args.size()) throw UsageError("option " + a + " needs a value");
            return args[++i];
        };
        if (a == "--algo") algo = value();
        else if (a == "--spp") { spp = parseNumber<int>(a, value()); if (spp < 1) throw UsageError("--spp must be at least 1"); }
        else if (a == "--time") {
            seconds = parseNumber<double>(a, value());
            if (!(seconds > 0.0) || !std::isfinite(seconds)) throw UsageError("--time must be a positive number of seconds");
        }
        else if (a == "--maxdepth") { maxDepth = parseNumber<int>(a, value()); if (maxDepth < 0) throw UsageError("--maxdepth must not be negative"); }
        else if (a == "--seed") seed = parseNumber<uint64_t>(a, value());
        else if (a == "--threads") { threads = parseNumber<int>(a, value()); if (threads < 1) throw UsageError("--threads must be at least 1"); }
        else if (a == "--out") out = value();
        else if (a == "--reference") reference = value();
        else if (a == "--csv") csvPath = value();
        else if (a == "--variance") variancePath = value();
        else if (a == "--progress") progress = true;
        else if (a == "--no-progress") progress = false;
        else if (a == "--no-prune") prune = false;
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else if (scenePath.empty()) scenePath = a;
        else throw UsageError("more than one scene given ('" + scenePath + "' and '" + a + "')");
    }
    if (scenePath.empty()) throw UsageError("'render' needs a scene file");

    ps::Scene scene = ps::loadScene(scenePath);
    if (maxDepth >= 0) scene.settings.maxDepth = maxDepth;
    scene.settings.prune = prune;
    std::unique_ptr<ps::Integrator> integrator;
    if (algo.empty()) {
        algo = scene.settings.algo;
        try {
            integrator = ps::makeIntegrator(algo);
        } catch (const ps::InputError& e) {   // name the scene line that asked for it
            throw ps::InputError(scenePath, scene.settings.algoLine, e.what());
        }
    } else {
        integrator = ps::makeIntegrator(algo);
    }
    if (spp == 0 && seconds == 0.0) spp = scene.settings.spp;
    if (out.empty()) out = stem(baseName(scenePath)) + ".png";

    ps::Image ref;
    std::ofstream csv;
    ps::RenderOptions opt;
    opt.spp = spp;
    opt.seconds = seconds;
    opt.seed = seed;
    opt.threads = threads;
    opt.progress = progress;
    if (!reference.empty()) {
        ref = ps::readImage(reference);
        if (ref.width != scene.camera.width() || ref.height != scene.camera.height())
            throw ps::InputError(reference, 0, "reference is " + std::to_string(ref.width) + "x" +
                                                   std::to_string(ref.height) + " but the scene renders " +
                                                   std::to_string(scene.camera.width()) + "x" +
                                                   std::to_string(scene.camera.height()));
        if (csvPath.empty()) csvPath = stem(out) + ".csv";
        csv.open(csvPath);
        if (!csv) throw ps::InputError(csvPath, 0, "cannot open for writing");
        opt.reference = &ref;
        opt.csv = &csv;
    }
    std::cerr << "pathspace: " << scenePath << " (" << scene.caps.describe() << "), algo " << algo << "\n";
    printLeftOut(algo, *integrator, scene);

    const ps::RenderResult res = ps::render(scene, *integrator, opt);
    const ps::Image img = res.film.mean();
    ps::writeImage(out, img);
    std::string written = out;
    if (stem(out) + ".pfm" != out) {
        ps::writePFM(stem(out) + ".pfm", img);
        written += ", " + stem(out) + ".pfm";
    }
    if (!variancePath.empty()) {
        ps::writePFM(variancePath, res.film.varianceOfMean());
        written += ", " + variancePath;
    }
    if (opt.csv) written += ", " + csvPath;
    std::cout << "pathspace: " << ps::summaryLine(res) << "; wrote " << written << "\n";
    if (res.stats.bad() > 0)
        std::cerr << "pathspace: warning: " << res.stats.bad()
                  << " samples were NaN or Inf; they were left out of the image (see the counts above)\n";
    return 0;
}

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : s + ",") {
        if (c == ',') { if (!cur.empty()) out.push_back(cur); cur.clear(); }
        else cur += c;
    }
    return out;
}

int converge(const std::vector<std::string>& args) {
    std::string scenePath, reference, refAlgo, outDir;
    std::vector<std::string> regionNames;
    ps::ConvergeOptions opt;
    opt.seconds = 0.0;
    opt.progress = isatty(2);
    double refSeconds = 0.0;
    int maxDepth = -1;
    bool prune = true;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= args.size()) throw UsageError("option " + a + " needs a value");
            return args[++i];
        };
        auto positive = [&](double v) {
            if (!(v > 0.0) || !std::isfinite(v)) throw UsageError(a + " must be a positive number");
            return v;
        };
        if (a == "--algos") opt.algos = splitList(value());
        else if (a == "--time") opt.seconds = positive(parseNumber<double>(a, value()));
        else if (a == "--spp") opt.spp = static_cast<int>(positive(parseNumber<int>(a, value())));
        else if (a == "--regions") regionNames = splitList(value());
        else if (a == "--reference") reference = value();
        else if (a == "--ref-algo") refAlgo = value();
        else if (a == "--ref-time") refSeconds = positive(parseNumber<double>(a, value()));
        else if (a == "--seeds") opt.seeds = static_cast<int>(positive(parseNumber<int>(a, value())));
        else if (a == "--threads") opt.threads = static_cast<int>(positive(parseNumber<int>(a, value())));
        else if (a == "--maxdepth") { maxDepth = parseNumber<int>(a, value()); if (maxDepth < 0) throw UsageError("--maxdepth must not be negative"); }
        else if (a == "--out") outDir = value();
        else if (a == "--progress") opt.progress = true;
        else if (a == "--no-progress") opt.progress = false;
        else if (a == "--no-prune") prune = false;
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else if (scenePath.empty()) scenePath = a;
        else throw UsageError("more than one scene given ('" + scenePath + "' and '" + a + "')");
    }
    if (scenePath.empty()) throw UsageError("'converge' needs a scene file");
    if (opt.algos.empty()) throw UsageError("'converge' needs --algos A,B,...");
    if (opt.seconds == 0.0 && opt.spp == 0) throw UsageError("'converge' needs --time SECONDS or --spp N");
    if (opt.seconds == 0.0 && reference.empty() && refSeconds == 0.0)
        throw UsageError("'converge' without --time needs --reference REF or --ref-time SECONDS");
    for (const std::string& a : opt.algos) ps::makeIntegrator(a);   // unknown names fail now, not later
    ps::Scene scene = ps::loadScene(scenePath);
    if (maxDepth >= 0) scene.settings.maxDepth = maxDepth;
    if (!regionNames.empty()) {
        try {
            opt.regions = ps::materialRegions(scene, regionNames);
        } catch (const ps::InputError& e) {
            throw ps::InputError(scenePath, 0, e.what());
        }
    }
    scene.settings.prune = prune;
    for (const std::string& a : opt.algos) printLeftOut(a, *ps::makeIntegrator(a), scene);
    const std::string name = stem(baseName(scenePath));
    if (outDir.empty()) outDir = "converge-" + name;
    ::mkdir(outDir.c_str(), 0755);
    struct stat st;
    if (::stat(outDir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) throw ps::InputError(outDir, 0, "cannot create the output folder");

    ps::Image ref, refVariance;
    if (!reference.empty()) {
        ref = ps::readImage(reference);
        if (ref.width != scene.camera.width() || ref.height != scene.camera.height())
            throw ps::InputError(reference, 0, "reference size differs from the scene's resolution");
    } else {
        if (refAlgo.empty()) refAlgo = opt.algos[0];
        auto integrator = ps::makeIntegrator(refAlgo);
        ps::RenderOptions ro;
        ro.seconds = refSeconds > 0.0 ? refSeconds : 10.0 * opt.seconds;
        ro.seed = 1000003;   // independent of the compared runs (seeds 0 .. K-1)
        ro.threads = opt.threads;
        ro.progress = opt.progress;
        std::cerr << "pathspace: rendering the reference with " << refAlgo << " for " << ro.seconds << " s\n";
        const ps::RenderResult r = ps::render(scene, *integrator, ro);
        ref = r.film.mean();
        refVariance = r.film.varianceOfMean();
        ps::writePFM(outDir + "/reference.pfm", ref);
        ps::writePFM(outDir + "/reference-variance.pfm", refVariance);
        std::cout << "pathspace: reference: " << ps::summaryLine(r) << "\n";
    }

    const ps::ConvergenceReport report = ps::runConvergence(scene, ref, opt);
    std::ofstream(outDir + "/convergence.csv") << ps::convergenceCsv(name, report);
    std::ofstream(outDir + "/convergence.svg")
        << ps::convergencePlotSvg(name + ": relMSE against render time (" + std::to_string(opt.seeds) + " seed(s))", report);
    const std::string table = ps::efficiencyTable(report);
    std::ostringstream budget;
    if (opt.seconds > 0.0) budget << opt.seconds << " s";
    if (opt.spp > 0) budget << (opt.seconds > 0.0 ? " or " : "") << opt.spp << " spp";
    std::ofstream(outDir + "/efficiency.md") << "Efficiency on " << name << " at " << budget.str()
                                             << " per algorithm (relMSE with eps = 0.01):\n\n" << table;
    std::vector<ps::Image> images = report.finalImages;
    images.push_back(ref);
    const ps::Image strip = ps::sideBySide(images);
    ps::writePNG(outDir + "/equal-time.png", strip);
    ps::writePFM(outDir + "/equal-time.pfm", strip);
    std::cout << table;
    if (!regionNames.empty()) {
        const std::string regions = ps::regionTable(report, opt.regions);
        std::ofstream(outDir + "/regions.md") << "relMSE (eps = 0.01) of each region of " << name
                                              << " (the pixels that see each material) at the end of the run:\n\n"
                                              << regions;
        std::cout << "\n" << regions;
    }
    // A reference must be much better than what it judges (../shared/notes/testing.md).
    if (!refVariance.pixels.empty()) {
        double var = 0.0, smallest = 1e300;
        for (const auto& c : refVariance.pixels) var += (double(c.r) + c.g + c.b) / 3.0;
        var /= double(refVariance.pixels.size());
        for (const auto& p : report.points) smallest = std::min(smallest, p.error.mse);
        if (smallest > 0.0 && var > 0.03 * smallest)
            std::cerr << "pathspace: warning: the reference's own variance (" << var << ") is more than 3 % of the "
                      << "smallest MSE reported (" << smallest << "): give it more time (--ref-time)\n";
    }
    std::cout << "pathspace: wrote " << outDir << "/{convergence.csv,convergence.svg,efficiency.md,equal-time.png"
              << (regionNames.empty() ? "" : ",regions.md") << "}\n";
    return 0;
}

// Veach's pyramid (lesson 7): every technique (s, t) of path lengths 1..K alone, as images laid
// out in rows k = 1..K, centred, row k holding s = 0..k+1.
int pyramid(const std::vector<std::string>& args) {
    std::string scenePath, out;
    int maxLength = 4, spp = 0, threads = 0;
    uint64_t seed = 0;
    float exposure = 0.0f;
    bool prune = true;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= args.size()) throw UsageError("option " + a + " needs a value");
            return args[++i];
        };
        if (a == "--max-length") { maxLength = parseNumber<int>(a, value()); if (maxLength < 1 || maxLength > 12) throw UsageError("--max-length must be 1..12"); }
        else if (a == "--spp") { spp = parseNumber<int>(a, value()); if (spp < 1) throw UsageError("--spp must be at least 1"); }
        else if (a == "--seed") seed = parseNumber<uint64_t>(a, value());
        else if (a == "--threads") { threads = parseNumber<int>(a, value()); if (threads < 1) throw UsageError("--threads must be at least 1"); }
        else if (a == "--exposure") exposure = parseNumber<float>(a, value());
        else if (a == "--out") out = value();
        else if (a == "--no-prune") prune = false;
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option " + a);
        else if (scenePath.empty()) scenePath = a;
        else throw UsageError("'pyramid' takes one scene file");
    }
    if (scenePath.empty()) throw UsageError("'pyramid' needs a scene file");
    ps::Scene scene = ps::loadScene(scenePath);
    scene.settings.prune = prune;
    if (spp == 0) spp = scene.settings.spp;
    if (out.empty()) out = stem(baseName(scenePath)) + "-pyramid";
    ps::BptOptions opt;
    for (const std::string& line : ps::bptLeftOut(scene, opt)) std::cerr << "pathspace: pyramid leaves out " << line << "\n";
    const ps::TechniqueImages t = ps::renderTechniques(scene, maxLength, spp, seed, threads, opt);
    const int w = scene.camera.width(), h = scene.camera.height(), gap = std::max(2, w / 16);
    const int cols = maxLength + 2;
    ps::Image unweighted(cols * (w + gap) + gap, maxLength * (h + gap) + gap, ps::Color(0.15f));
    ps::Image weighted = unweighted;
    std::cout << "pathspace: pyramid of " << scenePath << ", " << spp << " spp; row k = path length k (k edges), "
              << "cells s = 0..k+1 from the left (t = k+1-s):\n";
    for (int k = 1; k <= maxLength; ++k) {
        const int x0 = gap + (maxLength - k) * (w + gap) / 2, y0 = gap + (k - 1) * (h + gap);
        std::cout << "  k = " << k << ":";
        for (int s = 0; s <= k + 1; ++s) {
            const int idx = ps::techniqueIndex(s, k);
            const ps::Image& u = t.unweighted[size_t(idx)];
            const ps::Image& wt = t.weighted[size_t(idx)];
            double sum = 0.0;
            for (const auto& c : u.pixels) sum += double(c.r) + c.g + c.b;
            std::cout << "  (" << s << "," << k + 1 - s << ")" << (sum > 0.0 ? "" : " black");
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    unweighted.at(x0 + s * (w + gap) + x, y0 + y) = u.at(x, y);
                    weighted.at(x0 + s * (w + gap) + x, y0 + y) = wt.at(x, y);
                }
            const std::string name = out + "-" + std::to_string(s) + "-" + std::to_string(k + 1 - s);
            ps::writePFM(name + ".pfm", u);
            ps::writePFM(name + "-weighted.pfm", wt);
        }
        std::cout << "\n";
    }
    std::cout << "  black: the technique cannot sample (t = 0: the pinhole; s = 0 with point lights only; "
                 "a connection at a specular vertex) or found nothing at this spp\n";
    ps::writePNG(out + "-unweighted.png", unweighted, exposure);
    ps::writePNG(out + "-weighted.png", weighted, exposure);
    std::cout << "pathspace: " << t.stats.nan << " NaN, " << t.stats.inf << " Inf values (counted, left out of the images)\n";
    std::cout << "pathspace: wrote " << out << "-unweighted.png, " << out << "-weighted.png and " << out << "-S-T[-weighted].pfm\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    ps::preferPassiveWaiting(argv);
    std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
            std::cout << kUsage;
            return args.empty() ? 2 : 0;
        }
        const std::string cmd = args[0];
        args.erase(args.begin());
        for (const auto& a : args)
            if (a == "--help" || a == "-h") { std::cout << kUsage; listAlgorithms(); return 0; }
        if (cmd == "render") return render(args);
        if (cmd == "info") return info(args);
        if (cmd == "converge") return converge(args);
        if (cmd == "pyramid") return pyramid(args);
        throw UsageError("unknown command '" + cmd + "'");
    } catch (const UsageError& e) {
        std::cerr << "pathspace: " << e.what() << " (run 'pathspace --help' for usage)\n";
        return 2;
    } catch (const ps::InputError& e) {
        std::cerr << "pathspace: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "pathspace: internal error: " << e.what() << "\n";
        return 3;
    }
}
