// pathspace converge SCENE --algos A,B,... (--time SECONDS | --spp N) [options]: error against run
// time of several algorithms (the report itself: report/converge.h).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include "command.h"
#include "errors.h"
#include "file_writer.h"
#include "image.h"
#include "integrator.h"
#include "render.h"
#include "report/converge.h"
#include "report/label.h"
#include "scene_loader.h"

namespace ps {
namespace {

const char* const kUsage = R"(converge options:
  --algos A,B,...    the algorithms to compare (required)
  --time SECONDS     time budget of each algorithm (and seed)
  --clock C          the clock of --time, --ref-time and every time in the report: wall
                     (default), or cpu: the CPU time of the process, all threads added up
                     (fairer on a machine that other jobs share); the report names it
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
  --out DIR          where the report goes (default: converge-SCENE; made if missing); it holds
                     convergence.csv, convergence.svg (log-log relMSE against seconds with a
                     slope -1 guide), efficiency.md, equal-time.png (the algorithms' images at
                     the end of the budget, left to right in --algos order, then the reference,
                     each under its label: algorithm and spp)
  --threads T, --maxdepth D, --no-prune, --progress/--no-progress   as for render
  --NAME V,..        a render parameter (below) as for render, for every algorithm and --ref-algo
  an algorithm option (below, e.g. --paths EXPR) applies to every algorithm and --ref-algo (a
                     given --reference must be rendered with it too)
A pixel in which a point light is seen directly is left out of every algorithm's error (a path
tracer cannot sample that path: both ends are delta positions); the report says which.
)";

// What the command line asks for (parseConverge), before anything is loaded.
struct ConvergeArgs {
    std::string scenePath, reference, refAlgo, outDir;
    std::vector<std::string> regionNames;
    ConvergeOptions opt;
    double refSeconds = 0.0;
    int maxDepth = -1;
    bool prune = true;
    RenderParameterValues parameters;  // --elements 16x8 and the like (framework/scene.h)
    std::vector<std::string> files;    // what it writes into outDir, checked (command.h)
};

ConvergeArgs parseConverge(const std::vector<std::string>& args) {
    ConvergeArgs c;
    ConvergeOptions& opt = c.opt;
    opt.seconds = 0.0;
    opt.progress = stderrIsTerminal();
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string { return optionValue(args, i); };
        if (a == "--algos") opt.algos = splitList(value());
        else if (a == "--time") opt.seconds = parsePositive(a, value());
        else if (a == "--clock") opt.clock = parseClockOption(value());
        else if (a == "--spp") opt.spp = parseAtLeast<int>(a, value(), 1);
        else if (a == "--regions") c.regionNames = splitList(value());
        else if (a == "--reference") c.reference = value();
        else if (a == "--ref-algo") c.refAlgo = value();
        else if (a == "--ref-time") c.refSeconds = parsePositive(a, value());
        else if (a == "--seeds") opt.seeds = parseAtLeast<int>(a, value(), 1);
        else if (a == "--threads") opt.threads = parseWithin<int>(a, value(), 1, kMaxThreads);
        else if (a == "--maxdepth") c.maxDepth = parseAtLeast<int>(a, value(), 0);
        else if (a == "--out") c.outDir = value();
        else if (a == "--progress") opt.progress = true;
        else if (a == "--no-progress") opt.progress = false;
        else if (a == "--no-prune") c.prune = false;
        else if (parseAlgorithmOption(args, i, opt.options)) continue;
        else if (parseRenderParameterOption(args, i, c.parameters)) continue;
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else if (c.scenePath.empty()) c.scenePath = a;
        else throw UsageError("more than one scene given ('" + c.scenePath + "' and '" + a + "')");
    }
    if (c.scenePath.empty()) throw UsageError("'converge' needs a scene file");
    if (opt.algos.empty()) throw UsageError("'converge' needs --algos A,B,...");
    if (opt.seconds == 0.0 && opt.spp == 0) throw UsageError("'converge' needs --time SECONDS or --spp N");
    if (opt.seconds == 0.0 && c.reference.empty() && c.refSeconds == 0.0)
        throw UsageError("'converge' without --time needs --reference REF or --ref-time SECONDS");
    // Unknown names, and algorithms that refuse the options, fail now, not later.
    for (const std::string& a : opt.algos) makeAlgorithm(a, opt.options);
    if (!c.refAlgo.empty()) makeAlgorithm(c.refAlgo, opt.options);
    // The report's folder and every file in it, checked before the scene is loaded (command.h).
    if (c.outDir.empty()) c.outDir = "converge-" + stem(baseName(c.scenePath));
    std::vector<std::string> files = {"convergence.csv", "convergence.svg", "efficiency.md", "equal-time.png",
                                      "equal-time.pfm"};
    if (c.reference.empty()) files.insert(files.end(), {"reference.pfm", "reference-variance.pfm"});
    if (!c.regionNames.empty()) files.push_back("regions.md");
    std::vector<InputFile> inputs = {{"the scene file", c.scenePath, ""}};
    if (!c.reference.empty()) inputs.push_back({"the reference image", c.reference, "--reference"});
    checkOutputFolder("--out", c.outDir, files, inputs);
    c.files = files;
    return c;
}

int runConverge(ConvergeArgs c) {
    ConvergeOptions& opt = c.opt;
    const std::string& scenePath = c.scenePath;
    const std::string& outDir = c.outDir;
    const std::string& reference = c.reference;
    const std::vector<std::string>& regionNames = c.regionNames;
    std::string& refAlgo = c.refAlgo;
    const std::string name = stem(baseName(scenePath));
    Scene scene = loadScene(scenePath);
    {
        std::vector<OutputFile> outputs;
        for (const std::string& f : c.files) outputs.push_back({"--out", outDir + "/" + f, {}});
        checkNotInputs(outputs, sceneInputs(scene));  // its meshes and material libraries
    }
    if (c.maxDepth >= 0) scene.settings.maxDepth = c.maxDepth;
    setRenderParameters(c.parameters, scene.settings);
    if (!regionNames.empty()) {
        try {
            opt.regions = materialRegions(scene, regionNames);
        } catch (const InputError& e) { throw InputError(scenePath, 0, e.what()); }
    }
    scene.settings.prune = c.prune;
    for (const std::string& a : opt.algos) checkScene(scene, *makeAlgorithm(a, opt.options));  // e.g. a camera model
    if (reference.empty() && !refAlgo.empty()) checkScene(scene, *makeAlgorithm(refAlgo, opt.options));  // the same
    Image ref, refVariance;
    if (!reference.empty()) ref = readReference(reference, scene);  // its size before its pixels, then finite
    for (const std::string& a : opt.algos) printLeftOut(a, *makeAlgorithm(a, opt.options), scene);
    const std::vector<PointLightPixel> leftOut = pointLightsInView(scene);
    for (const PointLightPixel& p : leftOut) std::cerr << "pathspace: " << describe(p) << "\n";
    std::error_code ec;
    std::filesystem::create_directories(outDir, ec);
    if (!std::filesystem::is_directory(outDir, ec)) throw InputError(outDir, 0, "cannot create the output folder");

    if (reference.empty()) {
        if (refAlgo.empty()) refAlgo = opt.algos[0];
        auto integrator = makeAlgorithm(refAlgo, opt.options);
        RenderOptions ro;
        ro.seconds = c.refSeconds > 0.0 ? c.refSeconds : 10.0 * opt.seconds;
        ro.clock = opt.clock;
        ro.seed = 1000003;  // independent of the compared runs (seeds 0 .. K-1)
        ro.threads = opt.threads;
        ro.progress = opt.progress;
        std::cerr << "pathspace: rendering the reference with " << refAlgo << " for " << ro.seconds << " s\n";
        const RenderResult r = render(scene, *integrator, ro);
        ref = r.film.mean();
        refVariance = r.film.varianceOfMean();
        writePFM(outDir + "/reference.pfm", ref);
        writePFM(outDir + "/reference-variance.pfm", refVariance);
        std::cout << "pathspace: reference: " << summaryLine(r) << "\n";
    }

    const ConvergenceReport report = runConvergence(scene, ref, opt);
    writeFile(outDir + "/convergence.csv", convergenceCsv(name, report));
    writeFile(
        outDir + "/convergence.svg",
        convergencePlotSvg(name + ": relMSE against render time (" + std::to_string(opt.seeds) + " seed(s))", report));
    const std::string table = efficiencyTable(report);
    std::ostringstream budget;
    if (opt.seconds > 0.0) budget << opt.seconds << (opt.clock == TimeClock::Cpu ? " CPU s" : " s");
    if (opt.spp > 0) budget << (opt.seconds > 0.0 ? " or " : "") << opt.spp << " spp";
    std::ostringstream md;
    md << "Efficiency on " << name << " at " << budget.str() << " per algorithm (relMSE with eps = 0.01; time in "
       << clockUnit(opt.clock) << ", " << (opt.threads > 0 ? std::to_string(opt.threads) : std::string("all"))
       << " thread(s)):\n\n"
       << table;
    if (!report.leftOut.empty()) md << "\n";
    for (const PointLightPixel& p : report.leftOut) md << "Note: " << describe(p) << ".\n";
    writeFile(outDir + "/efficiency.md", md.str());
    std::vector<Image> images = report.finalImages;
    images.push_back(ref);
    // The PNG says what each image is (algorithm and samples per pixel at the end of the budget,
    // seed 0); the PFM holds the pixels only.
    std::vector<std::string> labels;
    for (const std::string& a : opt.algos) {
        int spp = 0;
        for (const ConvergencePoint& p : report.points)
            if (p.algo == a && p.seed == 0) spp = p.spp;
        labels.push_back(a + " " + std::to_string(spp) + " spp");
    }
    labels.push_back(reference.empty() ? "reference " + refAlgo : "reference");
    writePNG(outDir + "/equal-time.png", labelledStrip(images, labels, Color(1.0f)));
    writePFM(outDir + "/equal-time.pfm", sideBySide(images));
    std::cout << table;
    if (!regionNames.empty()) {
        const std::string regions = regionTable(report, opt.regions);
        writeFile(outDir + "/regions.md", "relMSE (eps = 0.01) of each region of " + name +
                                              " (the pixels that see each material) at the end of the run:\n\n" +
                                              regions);
        std::cout << "\n" << regions;
    }
    // A reference must be much better than what it judges (../shared/notes/testing.md).
    if (!refVariance.pixels.empty()) {
        const std::vector<bool> mask = leftOutMask(scene, report.leftOut);
        double var = 0.0, count = 0.0, smallest = 1e300;
        for (size_t i = 0; i < refVariance.pixels.size(); ++i) {
            if (i < mask.size() && mask[i]) continue;
            const auto& c = refVariance.pixels[i];
            var += (double(c.r) + c.g + c.b) / 3.0;
            count += 1.0;
        }
        var /= std::max(count, 1.0);
        for (const auto& p : report.points) smallest = std::min(smallest, p.error.mse);
        if (smallest > 0.0 && var > 0.03 * smallest)
            std::cerr << "pathspace: warning: the reference's own variance (" << var << ") is more than 3 % of the "
                      << "smallest MSE reported (" << smallest << "): give it more time (--ref-time)\n";
    }
    std::cout << "pathspace: wrote " << outDir << "/{convergence.csv,convergence.svg,efficiency.md,equal-time.png"
              << (regionNames.empty() ? "" : ",regions.md") << "}\n";
    return 0;
}

Command convergeCommand() {
    Command c;
    c.name = "converge";
    c.order = 20;
    c.synopsis = "converge SCENE --algos A,B,... (--time SECONDS | --spp N) [options]";
    c.summary = "error against run time of several algorithms";
    c.usage = kUsage;
    c.takesAlgorithms = true;
    c.run = [](const std::vector<std::string>& args) { return runConverge(parseConverge(args)); };
    return c;
}

}  // namespace

PS_REGISTER_COMMAND(convergeCommand());

}  // namespace ps
