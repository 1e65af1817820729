// pathspace: the command-line front end.  `pathspace --help` lists the commands.
#include <unistd.h>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>
#include "errors.h"
#include "image.h"
#include "integrator.h"
#include "render.h"
#include "scene_loader.h"

namespace {

const char* kUsage = R"(pathspace - a light transport course renderer

usage:
  pathspace render SCENE [options]   render a scene file (see scenes/README.md)
  pathspace info SCENE               print what the scene contains and needs
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
  --progress / --no-progress   progress bar on stderr (default: when stderr is a terminal)

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
    bool progress = isatty(2);
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
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else if (scenePath.empty()) scenePath = a;
        else throw UsageError("more than one scene given ('" + scenePath + "' and '" + a + "')");
    }
    if (scenePath.empty()) throw UsageError("'render' needs a scene file");

    ps::Scene scene = ps::loadScene(scenePath);
    if (maxDepth >= 0) scene.settings.maxDepth = maxDepth;
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

}  // namespace

int main(int argc, char** argv) {
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
