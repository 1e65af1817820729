// pathspace render SCENE [options]: one image with one integrator, progressively (framework/render.h).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include "command.h"
#include "errors.h"
#include "image.h"
#include "integrator.h"
#include "render.h"
#include "scene_loader.h"

namespace ps {
namespace {

const char* const kUsage = R"(render options:
  --algo NAME        integrator (default: the scene's 'render algo', else eyelight)
  --spp N            iterations (samples per pixel) to render (default: the scene's)
  --time SECONDS     stop after this much render time instead (with --spp: whichever first);
                     a positive finite number
  --maxdepth D       maximum number of bounces, 0 = emission seen directly (default: the scene's)
  --seed S           random seed (default 0); the same seed gives the same image
  --threads T        worker threads, 1 to 1024 (default: all cores); the image does not
                     depend on it
  --out FILE         output image, .png, .pfm, .hdr or .exr (default: SCENE's name + .png);
                     a .pfm with the exact values is always written next to the others
  --variance FILE    also write the per-pixel variance of the mean (FILE ends in .pfm)
  --reference REF    a reference image (.pfm or .hdr): log error against run time
  --csv FILE         where that log goes (default: the output's name + .csv)
  --elements N[xM]   radiosity only: cut every quad into N x M elements (default: the scene's
                     'render elements', else 8x8; N, M from 1 to 256)
  --shots S          radiosity only: shooting steps per iteration (default: the scene's
                     'render shots', else 256)
  --no-prune         do not leave out work the scene cannot use (integrators print what
                     they leave out; pruning is exact, this switch is there to check it)
  --progress / --no-progress   progress bar on stderr (default: when stderr is a terminal)
  --ambient A        whitted's ambient radiance, one number or R,G,B (default: the scene's
                     'render ambient', else 0)
  --guide-budget MB  pt-guided and pt-guided-adrrs only: the most memory their learned field
                     may take, in MB (default 64; from 0.01 to 65536)
)";

int runRender(const std::vector<std::string>& args) {
    std::string scenePath, algo, out, reference, csvPath, variancePath;
    int spp = 0, threads = 0, maxDepth = -1, shots = 0, elements[2] = {0, 0};
    double seconds = 0.0;
    uint64_t seed = 0;
    bool progress = stderrIsTerminal(), prune = true;
    std::optional<PathExpression> paths;
    std::optional<Color> ambient;
    double guideBudget = 0.0;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string { return optionValue(args, i); };
        if (a == "--algo") algo = value();
        else if (a == "--spp") spp = parseAtLeast<int>(a, value(), 1);
        else if (a == "--time") seconds = parsePositive(a, value());
        else if (a == "--maxdepth") maxDepth = parseAtLeast<int>(a, value(), 0);
        else if (a == "--seed") seed = parseNumber<uint64_t>(a, value());
        else if (a == "--threads") threads = parseWithin<int>(a, value(), 1, kMaxThreads);
        else if (a == "--out") out = value();
        else if (a == "--reference") reference = value();
        else if (a == "--csv") csvPath = value();
        else if (a == "--variance") variancePath = value();
        else if (a == "--progress") progress = true;
        else if (a == "--no-progress") progress = false;
        else if (a == "--no-prune") prune = false;
        else if (a == "--paths") paths = parsePathsOption(value());
        else if (a == "--ambient") ambient = parseAmbient(a, value());
        else if (a == "--guide-budget") guideBudget = parseWithin<double>(a, value(), 0.01, 65536.0);
        else if (a == "--shots") shots = parseAtLeast<int>(a, value(), 1);
        else if (a == "--elements") {
            const std::string v = value();
            const size_t x = v.find('x');
            elements[0] = parseWithin<int>(a, v.substr(0, x), 1, kMaxElements);
            elements[1] = x == std::string::npos ? elements[0] : parseWithin<int>(a, v.substr(x + 1), 1, kMaxElements);
        } else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else if (scenePath.empty()) scenePath = a;
        else throw UsageError("more than one scene given ('" + scenePath + "' and '" + a + "')");
    }
    if (scenePath.empty()) throw UsageError("'render' needs a scene file");
    if (paths && !algo.empty()) {
        makeIntegrator(algo);  // an unknown name says so first
        requirePathFilter(algo, *paths);
    }
    // Every file this run writes, checked before the scene is loaded (command.h).
    if (out.empty()) out = stem(baseName(scenePath)) + ".png";
    std::vector<OutputFile> outputs = {{"--out", out, imageExtensions()}};
    if (stem(out) + ".pfm" != out) outputs.push_back({"--out", stem(out) + ".pfm", {".pfm"}});  // written next to it
    if (!variancePath.empty()) outputs.push_back({"--variance", variancePath, {".pfm"}});
    if (!reference.empty()) {
        if (csvPath.empty()) csvPath = stem(out) + ".csv";
        outputs.push_back({"--csv", csvPath, {}});
    }
    checkOutputFiles(outputs);

    Scene scene = loadScene(scenePath);
    if (maxDepth >= 0) scene.settings.maxDepth = maxDepth;
    scene.settings.prune = prune;
    if (ambient) scene.settings.ambient = *ambient;
    if (guideBudget > 0.0) scene.settings.guideBudget = size_t(guideBudget * double(1 << 20));
    if (shots > 0) scene.settings.shots = shots;
    if (elements[0] > 0) std::copy(elements, elements + 2, scene.settings.elements);
    std::unique_ptr<Integrator> integrator;
    if (algo.empty()) {
        algo = scene.settings.algo;
        try {
            integrator = makeIntegrator(algo);
        } catch (const InputError& e) {  // name the scene line that asked for it
            throw InputError(scenePath, scene.settings.algoLine, e.what());
        }
        if (paths) requirePathFilter(algo, *paths);
    }
    if (paths) integrator = makeIntegrator(algo, &*paths);
    else if (!integrator) integrator = makeIntegrator(algo);
    if (spp == 0 && seconds == 0.0) spp = scene.settings.spp;
    integrator->checkScene(scene);    // a refusal (InputError) before anything is printed
    checkCamera(scene, *integrator);  // a thin lens it cannot render: one error line, before anything else

    Image ref;
    std::ofstream csv;
    RenderOptions opt;
    opt.spp = spp;
    opt.seconds = seconds;
    opt.seed = seed;
    opt.threads = threads;
    opt.progress = progress;
    if (!reference.empty()) {
        ref = readImage(reference);
        if (ref.width != scene.camera.width() || ref.height != scene.camera.height())
            throw InputError(reference, 0,
                             "reference is " + std::to_string(ref.width) + "x" + std::to_string(ref.height) +
                                 " but the scene renders " + std::to_string(scene.camera.width()) + "x" +
                                 std::to_string(scene.camera.height()));
        csv.open(csvPath);
        if (!csv) throw InputError(csvPath, 0, "cannot open for writing");
        opt.reference = &ref;
        opt.csv = &csv;
    }
    std::cerr << "pathspace: " << scenePath << " (" << scene.caps.describe() << "), algo " << algo
              << (paths ? ", paths '" + paths->text() + "'" : std::string()) << "\n";
    printLeftOut(algo, *integrator, scene);

    const RenderResult res = ps::render(scene, *integrator, opt);
    const Image img = res.film.mean();
    writeImage(out, img);
    std::string written = out;
    if (stem(out) + ".pfm" != out) {
        writePFM(stem(out) + ".pfm", img);
        written += ", " + stem(out) + ".pfm";
    }
    if (!variancePath.empty()) {
        writePFM(variancePath, res.film.varianceOfMean());
        written += ", " + variancePath;
    }
    if (opt.csv) written += ", " + csvPath;
    std::cout << "pathspace: " << summaryLine(res) << "; wrote " << written << "\n";
    for (const std::string& line : integrator->report()) std::cout << "pathspace: " << algo << ": " << line << "\n";
    if (res.stats.bad() > 0)
        std::cerr << "pathspace: warning: " << res.stats.bad()
                  << " samples were NaN or Inf; they were left out of the image (see the counts above)\n";
    return 0;
}

const std::string kRenderUsage = std::string(kUsage) + kPathsHelp;

}  // namespace

PS_REGISTER_COMMAND(render, 10, "render SCENE [options]", "render a scene file (see scenes/README.md)", kRenderUsage,
                    true, runRender);

}  // namespace ps
