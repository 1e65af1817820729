// pathspace render SCENE [options]: one image with one integrator, progressively (framework/render.h).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>
#include "command.h"
#include "errors.h"
#include "file_writer.h"
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
  --clock C          the clock of --time and of the time printed: wall (default), or cpu:
                     the CPU time of the process, all threads added up (fairer on a machine
                     that other jobs share; with T threads busy, T CPU s per second)
  --maxdepth D       maximum number of bounces, 0 = emission seen directly (default: the scene's)
  --seed S           random seed (default 0); the same seed gives the same image
  --threads T        worker threads, 1 to 1024 (default: all cores); the image does not
                     depend on it
  --out FILE         output image, .png, .pfm, .hdr or .exr (default: SCENE's name + .png);
                     a .pfm with the exact values is always written next to the others
  --variance FILE    also write the per-pixel variance of the mean (FILE ends in .pfm)
  --reference REF    a reference image (.pfm or .hdr): log error against run time
  --csv FILE         where that log goes (default: the output's name + .csv)
  --no-prune         do not leave out work the scene cannot use (integrators print what
                     they leave out; pruning is exact, this switch is there to check it)
  --progress / --no-progress   progress bar on stderr (default: when stderr is a terminal)
  --NAME V,..        a render parameter some algorithms read (listed below), over the scene's
)";

// What the command line asks for (parseRender), before anything is loaded.
struct RenderArgs {
    std::string scenePath, algo, out, reference, csvPath, variancePath;
    int spp = 0, threads = 0, maxDepth = -1;
    double seconds = 0.0;
    TimeClock clock = TimeClock::Wall;
    uint64_t seed = 0;
    bool progress = false, prune = true;
    AlgorithmOptions options;          // --paths EXPR and the like (integrator.h)
    RenderParameterValues parameters;  // --elements 16x8 and the like (framework/scene.h)
    std::vector<OutputFile> outputs;   // every file it writes, checked (command.h)
};

RenderArgs parseRender(const std::vector<std::string>& args) {
    RenderArgs r;
    r.progress = stderrIsTerminal();
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string { return optionValue(args, i); };
        if (a == "--algo") r.algo = value();
        else if (a == "--spp") r.spp = parseAtLeast<int>(a, value(), 1);
        else if (a == "--time") r.seconds = parsePositive(a, value());
        else if (a == "--clock") r.clock = parseClockOption(value());
        else if (a == "--maxdepth") r.maxDepth = parseAtLeast<int>(a, value(), 0);
        else if (a == "--seed") r.seed = parseNumber<uint64_t>(a, value());
        else if (a == "--threads") r.threads = parseWithin<int>(a, value(), 1, kMaxThreads);
        else if (a == "--out") r.out = value();
        else if (a == "--reference") r.reference = value();
        else if (a == "--csv") r.csvPath = value();
        else if (a == "--variance") r.variancePath = value();
        else if (a == "--progress") r.progress = true;
        else if (a == "--no-progress") r.progress = false;
        else if (a == "--no-prune") r.prune = false;
        else if (parseAlgorithmOption(args, i, r.options)) continue;
        else if (parseRenderParameterOption(args, i, r.parameters)) continue;
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else if (r.scenePath.empty()) r.scenePath = a;
        else throw UsageError("more than one scene given ('" + r.scenePath + "' and '" + a + "')");
    }
    if (r.scenePath.empty()) throw UsageError("'render' needs a scene file");
    if (!r.options.empty() && !r.algo.empty()) makeAlgorithm(r.algo, r.options);  // refused before anything is loaded
    // Every file this run writes, checked before the scene is loaded (command.h).
    if (r.out.empty()) r.out = stem(baseName(r.scenePath)) + ".png";
    std::vector<OutputFile> outputs = {{"--out", r.out, imageExtensions()}};
    if (stem(r.out) + ".pfm" != r.out)
        outputs.push_back({"--out", stem(r.out) + ".pfm", {".pfm"}});  // written next to it
    if (!r.variancePath.empty()) outputs.push_back({"--variance", r.variancePath, {".pfm"}});
    if (!r.reference.empty()) {
        if (r.csvPath.empty()) r.csvPath = stem(r.out) + ".csv";
        outputs.push_back({"--csv", r.csvPath, {}});
    }
    std::vector<InputFile> inputs = {{"the scene file", r.scenePath, ""}};
    if (!r.reference.empty()) inputs.push_back({"the reference image", r.reference, "--reference"});
    checkOutputFiles(outputs, inputs);
    r.outputs = outputs;
    return r;
}

int runRender(RenderArgs r) {
    Scene scene = loadScene(r.scenePath);
    checkNotInputs(r.outputs, sceneInputs(scene));  // its meshes and material libraries
    if (r.maxDepth >= 0) scene.settings.maxDepth = r.maxDepth;
    scene.settings.prune = r.prune;
    setRenderParameters(r.parameters, scene.settings);
    std::unique_ptr<Integrator> integrator;
    if (r.algo.empty()) {
        r.algo = scene.settings.algo;
        try {
            makeIntegrator(r.algo);
        } catch (const InputError& e) {  // name the scene line that asked for it
            throw InputError(r.scenePath, scene.settings.algoLine, e.what());
        }
    }
    integrator = makeAlgorithm(r.algo, r.options);
    if (r.spp == 0 && r.seconds == 0.0) r.spp = scene.settings.spp;
    checkScene(scene, *integrator);  // a refusal (InputError) before anything is printed

    Image ref;
    std::unique_ptr<FileStream> csv;  // the error log, written while the render runs
    RenderOptions opt;
    opt.spp = r.spp;
    opt.seconds = r.seconds;
    opt.clock = r.clock;
    opt.seed = r.seed;
    opt.threads = r.threads;
    opt.progress = r.progress;
    if (!r.reference.empty()) {
        ref = readReference(r.reference, scene);  // the size before the pixels, then finite
        csv = std::make_unique<FileStream>(r.csvPath);
        opt.reference = &ref;
        opt.csv = csv.get();
    }
    std::cerr << "pathspace: " << r.scenePath << " (" << scene.caps.describe() << "), algo " << r.algo;
    for (const auto& [name, value] : r.options) std::cerr << ", " << name << " '" << value << "'";
    std::cerr << "\n";
    printLeftOut(r.algo, *integrator, scene);

    const RenderResult res = ps::render(scene, *integrator, opt);
    const Image img = res.film.mean();
    writeImage(r.out, img);
    std::string written = r.out;
    if (stem(r.out) + ".pfm" != r.out) {
        writePFM(stem(r.out) + ".pfm", img);
        written += ", " + stem(r.out) + ".pfm";
    }
    if (!r.variancePath.empty()) {
        writePFM(r.variancePath, res.film.varianceOfMean());
        written += ", " + r.variancePath;
    }
    if (csv) {
        csv->close();
        written += ", " + r.csvPath;
    }
    std::cout << "pathspace: " << summaryLine(res) << "; wrote " << written << "\n";
    for (const std::string& line : integrator->report()) std::cout << "pathspace: " << r.algo << ": " << line << "\n";
    if (res.stats.bad() > 0)
        std::cerr << "pathspace: warning: " << res.stats.bad()
                  << " samples were NaN or Inf; they were left out of the image (see the counts above)\n";
    return 0;
}

Command renderCommand() {
    Command c;
    c.name = "render";
    c.order = 10;
    c.synopsis = "render SCENE [options]";
    c.summary = "render a scene file (see scenes/README.md)";
    c.usage = kUsage;
    c.takesAlgorithms = true;
    c.run = [](const std::vector<std::string>& args) { return runRender(parseRender(args)); };
    return c;
}

}  // namespace

PS_REGISTER_COMMAND(renderCommand());

}  // namespace ps
