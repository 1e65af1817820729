// pathspace pyramid SCENE [options]: Veach's pyramid. An algorithm that combines several sampling
// techniques (bidirectional path tracing, lesson 7, and whatever registers per-technique images:
// IntegratorCaps::techniqueImages) renders every technique alone, as images laid out in rows, one
// per path length, centred; the algorithm says which cells a row has.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include "command.h"
#include "image.h"
#include "render.h"
#include "report/label.h"
#include "scene_loader.h"

namespace ps {
namespace {

const char* const kUsage = R"(pyramid options:
  --algo NAME        the algorithm whose techniques are drawn (default bpt; those that have
                     per-technique images are listed in the error when another is given)
  --max-length K     path lengths 1..K (K edges at most, 1 to 12; default 4); row k of the
                     pyramid holds the algorithm's techniques of length k, e.g. bpt's s = 0..k+1
                     (t = k+1-s) from left to right
  --spp N            samples per pixel (default: the scene's)
  --seed S, --threads T, --no-prune   as for render; an algorithm option (e.g. --paths EXPR: each
                     technique's image holds only the paths EXPR matches) and a render
                     parameter (--NAME V,..) as for render
  --exposure E       PNG exposure in stops, -100 to 100 (default 0)
  --out PREFIX       writes PREFIX-unweighted.png (each technique alone, its unweighted
                     estimate), PREFIX-weighted.png (the MIS-weighted ones: a row adds up
                     to the paths of that length), PREFIX-CELL.pfm and PREFIX-CELL-weighted.pfm
                     for each cell (bpt: CELL = s-t; default PREFIX: SCENE's name + -pyramid);
                     cells of techniques that cannot sample the scene's paths stay black
                     (listed on stdout)
)";

constexpr int kMaxLength = 12;
constexpr float kMaxExposure = 100.0f;  // 2^100 still fits a float

// What the command line asks for (parsePyramid), before anything is loaded.
struct PyramidArgs {
    std::string scenePath, out, algo = "bpt";
    TechniqueImagesOptions images;
    float exposure = 0.0f;
    bool prune = true;
    AlgorithmOptions options;
    RenderParameterValues parameters;  // --NAME V,.. (framework/scene.h)
    std::unique_ptr<Integrator> integrator;
    std::vector<TechniqueRow> layout;
    std::vector<OutputFile> outputs;  // every file it writes, checked (command.h)
};

// The memory a pyramid takes (scenes/README.md, 'Memory'): each cell keeps its unweighted and
// weighted images with their sums, about 90 bytes per pixel (peak memory, /usr/bin/time, 256 x 256
// pixels, bpt: 17, 107 and 556 MB for --max-length 1, 4 and 12, i.e. 3, 18 and 102 cells), on top
// of the algorithm's own (bpt: 126 bytes per pixel). A pyramid that would take more than the
// budget every render keeps within is refused before anything is rendered. The estimate is on the
// safe side (2048 x 2048, --max-length 1: 0.77 GB measured, 1.8 GB estimated).
constexpr double kCellBytesPerPixel = 100.0;       // measured 83 to 91, rounded up
constexpr double kAlgorithmBytesPerPixel = 130.0;  // bpt's 126 (the algorithms with per-technique images)
constexpr double kMemoryBudget = 3.0 * double(1u << 30);

void checkPyramidMemory(const PyramidArgs& p, const Scene& scene) {
    size_t cells = 0;
    for (const TechniqueRow& row : p.layout) cells += row.cells.size();
    const double pixels = double(scene.camera.width()) * scene.camera.height();
    const double bytes = pixels * (kAlgorithmBytesPerPixel + kCellBytesPerPixel * double(cells));
    if (bytes <= kMemoryBudget) return;
    char need[32];
    std::snprintf(need, sizeof need, "%.1f", bytes / double(1u << 30));
    throw UsageError("option --max-length " + std::to_string(p.images.maxLength) + ": " + std::to_string(cells) +
                     " technique images of " + std::to_string(scene.camera.width()) + " x " +
                     std::to_string(scene.camera.height()) + " pixels need about " + need +
                     " GiB, more than the 3 GiB a render may take (scenes/README.md, 'Memory'): lower --max-length "
                     "or the scene's resolution");
}

PyramidArgs parsePyramid(const std::vector<std::string>& args) {
    PyramidArgs p;
    p.images.spp = 0;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string { return optionValue(args, i); };
        if (a == "--algo") p.algo = value();
        else if (a == "--max-length") p.images.maxLength = parseWithin<int>(a, value(), 1, kMaxLength);
        else if (a == "--spp") p.images.spp = parseAtLeast<int>(a, value(), 1);
        else if (a == "--seed") p.images.seed = parseNumber<uint64_t>(a, value());
        else if (a == "--threads") p.images.threads = parseWithin<int>(a, value(), 1, kMaxThreads);
        else if (a == "--exposure") p.exposure = parseWithin<float>(a, value(), -kMaxExposure, kMaxExposure);
        else if (a == "--out") p.out = value();
        else if (a == "--no-prune") p.prune = false;
        else if (parseAlgorithmOption(args, i, p.options)) continue;
        else if (parseRenderParameterOption(args, i, p.parameters)) continue;
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else if (p.scenePath.empty()) p.scenePath = a;
        else throw UsageError("'pyramid' takes one scene file");
    }
    if (p.scenePath.empty()) throw UsageError("'pyramid' needs a scene file");
    p.integrator = makeAlgorithm(p.algo, p.options);
    if (!p.integrator->caps.techniqueImages) {
        std::string can;
        for (const IntegratorInfo& info : integratorList())
            if (info.caps.techniqueImages) can += (can.empty() ? "" : ", ") + info.name;
        throw UsageError("algorithm '" + p.algo + "' has no per-technique images; these have: " + can);
    }
    // Every file this run writes, checked before the scene is loaded (command.h).
    if (p.out.empty()) p.out = stem(baseName(p.scenePath)) + "-pyramid";
    std::vector<OutputFile> outputs = {{"--out", p.out + "-unweighted.png", {".png"}},
                                       {"--out", p.out + "-weighted.png", {".png"}}};
    p.layout = p.integrator->techniques.layout(p.images.maxLength);
    for (const TechniqueRow& row : p.layout)
        for (const TechniqueCell& cell : row.cells) {
            outputs.push_back({"--out", p.out + "-" + cell.name + ".pfm", {".pfm"}});
            outputs.push_back({"--out", p.out + "-" + cell.name + "-weighted.pfm", {".pfm"}});
        }
    checkOutputFiles(outputs, {{"the scene file", p.scenePath, ""}});
    p.outputs = outputs;
    return p;
}

int runPyramid(PyramidArgs p) {
    Scene scene = loadScene(p.scenePath);
    checkNotInputs(p.outputs, sceneInputs(scene));  // its meshes and material libraries
    scene.settings.prune = p.prune;
    setRenderParameters(p.parameters, scene.settings);
    if (p.images.spp == 0) p.images.spp = scene.settings.spp;
    checkScene(scene, *p.integrator);
    checkPyramidMemory(p, scene);
    for (const std::string& line : p.integrator->leftOut(scene))
        std::cerr << "pathspace: pyramid leaves out " << line << "\n";
    const TechniquePyramid t = p.integrator->techniques.render(scene, p.images);
    const int w = scene.camera.width(), h = scene.camera.height(), gap = std::max(2, w / 16);
    size_t cols = 0;
    for (const TechniqueRow& row : t.rows) cols = std::max(cols, row.cells.size());
    const int rows = static_cast<int>(t.rows.size());
    // Each cell under its label, the first of a row under the row's label too (label.h); the ink
    // is white after the PNG's exposure.
    const int scale = labelScale(w), band = (kGlyphHeight + 2) * scale;
    const Color ink(std::exp2(-p.exposure));
    Image unweighted(int(cols) * (w + gap) + gap, rows * (h + band + gap) + gap, Color(0.15f));
    Image weighted = unweighted;
    std::cout << "pathspace: pyramid of " << p.scenePath << " by " << p.algo << describeOptions(p.options) << ", "
              << p.images.spp << " spp; one row per path length:\n";
    for (int r = 0; r < rows; ++r) {
        const TechniqueRow& row = t.rows[size_t(r)];
        const int n = static_cast<int>(row.cells.size());
        const int x0 = gap + (int(cols) - n) * (w + gap) / 2, y0 = gap + r * (h + band + gap) + band;
        std::cout << "  " << row.label << ":";
        for (int c = 0; c < n; ++c) {
            const TechniqueCell& cell = row.cells[size_t(c)];
            double sum = 0.0;
            for (const auto& v : cell.unweighted.pixels) sum += double(v.r) + v.g + v.b;
            std::cout << "  " << cell.label << (sum > 0.0 ? "" : " black");
            const std::string label = c == 0 ? row.label + " " + cell.label : cell.label;
            const int lx = x0 + c * (w + gap), ly = y0 - band + scale / 2;
            drawText(unweighted, lx, ly, label, scale, ink, lx + w);
            drawText(weighted, lx, ly, label, scale, ink, lx + w);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    unweighted.at(lx + x, y0 + y) = cell.unweighted.at(x, y);
                    weighted.at(lx + x, y0 + y) = cell.weighted.at(x, y);
                }
            writePFM(p.out + "-" + cell.name + ".pfm", cell.unweighted);
            writePFM(p.out + "-" + cell.name + "-weighted.pfm", cell.weighted);
        }
        std::cout << "\n";
    }
    std::cout << "  black: the technique cannot sample these paths on this scene (its leaves-out lines say why), or "
                 "found nothing at this spp\n";
    writePNG(p.out + "-unweighted.png", unweighted, p.exposure);
    writePNG(p.out + "-weighted.png", weighted, p.exposure);
    std::cout << "pathspace: " << t.stats.nan << " NaN, " << t.stats.inf
              << " Inf values (counted, left out of the images)\n";
    std::cout << "pathspace: wrote " << p.out << "-unweighted.png, " << p.out << "-weighted.png and " << p.out
              << "-CELL[-weighted].pfm\n";
    return 0;
}

Command pyramidCommand() {
    Command c;
    c.name = "pyramid";
    c.order = 40;
    c.synopsis = "pyramid SCENE [options]";
    c.summary =
        "Veach's pyramid: the image of every technique of a bidirectional algorithm alone (s, t), per path length";
    c.usage = kUsage;
    c.takesAlgorithms = true;
    c.run = [](const std::vector<std::string>& args) { return runPyramid(parsePyramid(args)); };
    return c;
}

}  // namespace

PS_REGISTER_COMMAND(pyramidCommand());

}  // namespace ps
