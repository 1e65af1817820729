// pathspace pyramid SCENE [options]: Veach's pyramid (lesson 7). Every technique (s, t) of path
// lengths 1..K alone, as images laid out in rows k = 1..K, centred, row k holding s = 0..k+1.
// (Lesson 7's plumbing: it could live in lessons/07-bidirectional/ next to the integrator.)
#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include "07-bidirectional/bpt.h"
#include "11-classics/path_filter.h"
#include "command.h"
#include "image.h"
#include "report/label.h"
#include "scene_loader.h"

namespace ps {
namespace {

const char* const kUsage = R"(pyramid options:
  --max-length K     path lengths 1..K (K edges at most, 1 to 12; default 4); row k of the
                     pyramid holds the techniques s = 0..k+1 (t = k+1-s) from left to right
  --spp N            samples per pixel (default: the scene's)
  --seed S, --threads T, --no-prune, --paths EXPR   as for render (--paths: each technique's
                     image holds only the paths EXPR matches)
  --exposure E       PNG exposure in stops, -100 to 100 (default 0)
  --out PREFIX       writes PREFIX-unweighted.png (each technique alone, its unweighted
                     estimate), PREFIX-weighted.png (the MIS-weighted ones: a row adds up
                     to the paths of that length), PREFIX-s-t.pfm and PREFIX-s-t-weighted.pfm
                     for each technique (default: SCENE's name + -pyramid); cells of techniques
                     that cannot sample the scene's paths stay black (listed on stdout)
)";

constexpr int kMaxLength = 12;
constexpr float kMaxExposure = 100.0f;  // 2^100 still fits a float

int runPyramid(const std::vector<std::string>& args) {
    std::string scenePath, out;
    int maxLength = 4, spp = 0, threads = 0;
    uint64_t seed = 0;
    float exposure = 0.0f;
    bool prune = true;
    std::optional<PathExpression> paths;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string { return optionValue(args, i); };
        if (a == "--max-length") maxLength = parseWithin<int>(a, value(), 1, kMaxLength);
        else if (a == "--spp") spp = parseAtLeast<int>(a, value(), 1);
        else if (a == "--seed") seed = parseNumber<uint64_t>(a, value());
        else if (a == "--threads") threads = parseWithin<int>(a, value(), 1, kMaxThreads);
        else if (a == "--exposure") exposure = parseWithin<float>(a, value(), -kMaxExposure, kMaxExposure);
        else if (a == "--out") out = value();
        else if (a == "--no-prune") prune = false;
        else if (a == "--paths") paths = parsePathsOption(value());
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else if (scenePath.empty()) scenePath = a;
        else throw UsageError("'pyramid' takes one scene file");
    }
    if (scenePath.empty()) throw UsageError("'pyramid' needs a scene file");
    // Every file this run writes, checked before the scene is loaded (command.h).
    if (out.empty()) out = stem(baseName(scenePath)) + "-pyramid";
    std::vector<OutputFile> outputs = {{"--out", out + "-unweighted.png", {".png"}},
                                       {"--out", out + "-weighted.png", {".png"}}};
    for (int k = 1; k <= maxLength; ++k)
        for (int s = 0; s <= k + 1; ++s) {
            const std::string name = out + "-" + std::to_string(s) + "-" + std::to_string(k + 1 - s);
            outputs.push_back({"--out", name + ".pfm", {".pfm"}});
            outputs.push_back({"--out", name + "-weighted.pfm", {".pfm"}});
        }
    checkOutputFiles(outputs, {{"the scene file", scenePath, ""}});
    Scene scene = loadScene(scenePath);
    checkNotInputs(outputs, sceneInputs(scene));  // its meshes and material libraries
    scene.settings.prune = prune;
    if (spp == 0) spp = scene.settings.spp;
    BptOptions opt;
    for (const std::string& line : bptLeftOut(scene, opt))
        std::cerr << "pathspace: pyramid leaves out " << line << "\n";
    if (paths) {  // lesson 11's filter, as in `bpt --paths`
        opt.pathTest = [&](const Subpath& light, const Subpath& camera, int s, int t) {
            return bptPathMatches(*paths, scene, light, camera, s, t);
        };
        for (const std::string& line : pathFilterLeftOut(
                 *paths, scene, "a technique connects (traces its shadow ray) only where its path matches"))
            std::cerr << "pathspace: pyramid leaves out " << line << "\n";
    }
    const TechniqueImages t = renderTechniques(scene, maxLength, spp, seed, threads, opt);
    const int w = scene.camera.width(), h = scene.camera.height(), gap = std::max(2, w / 16);
    const int cols = maxLength + 2;
    // Each cell under its label "(s,t)", the first of a row under "k=K (0,t)" too (label.h); the
    // ink is white after the PNG's exposure.
    const int scale = labelScale(w), band = (kGlyphHeight + 2) * scale;
    const Color ink(std::exp2(-exposure));
    Image unweighted(cols * (w + gap) + gap, maxLength * (h + band + gap) + gap, Color(0.15f));
    Image weighted = unweighted;
    std::cout << "pathspace: pyramid of " << scenePath << ", " << spp << " spp; row k = path length k (k edges), "
              << "cells s = 0..k+1 from the left (t = k+1-s):\n";
    for (int k = 1; k <= maxLength; ++k) {
        const int x0 = gap + (maxLength - k) * (w + gap) / 2, y0 = gap + (k - 1) * (h + band + gap) + band;
        std::cout << "  k = " << k << ":";
        for (int s = 0; s <= k + 1; ++s) {
            const int idx = techniqueIndex(s, k);
            const Image& u = t.unweighted[size_t(idx)];
            const Image& wt = t.weighted[size_t(idx)];
            double sum = 0.0;
            for (const auto& c : u.pixels) sum += double(c.r) + c.g + c.b;
            std::cout << "  (" << s << "," << k + 1 - s << ")" << (sum > 0.0 ? "" : " black");
            const std::string st = "(" + std::to_string(s) + "," + std::to_string(k + 1 - s) + ")";
            const std::string label = s == 0 ? "k=" + std::to_string(k) + " " + st : st;
            const int lx = x0 + s * (w + gap), ly = y0 - band + scale / 2;
            drawText(unweighted, lx, ly, label, scale, ink, lx + w);
            drawText(weighted, lx, ly, label, scale, ink, lx + w);
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    unweighted.at(x0 + s * (w + gap) + x, y0 + y) = u.at(x, y);
                    weighted.at(x0 + s * (w + gap) + x, y0 + y) = wt.at(x, y);
                }
            const std::string name = out + "-" + std::to_string(s) + "-" + std::to_string(k + 1 - s);
            writePFM(name + ".pfm", u);
            writePFM(name + "-weighted.pfm", wt);
        }
        std::cout << "\n";
    }
    std::cout << "  black: the technique cannot sample (t = 0: a pinhole camera; s = 0 with point lights only; "
                 "a connection at a specular vertex) or found nothing at this spp\n";
    writePNG(out + "-unweighted.png", unweighted, exposure);
    writePNG(out + "-weighted.png", weighted, exposure);
    std::cout << "pathspace: " << t.stats.nan << " NaN, " << t.stats.inf
              << " Inf values (counted, left out of the images)\n";
    std::cout << "pathspace: wrote " << out << "-unweighted.png, " << out << "-weighted.png and " << out
              << "-S-T[-weighted].pfm\n";
    return 0;
}

}  // namespace

PS_REGISTER_COMMAND(pyramid, 40, "pyramid SCENE [options]",
                    "Veach's pyramid: the image of every bidirectional technique (s, t) alone, per path length "
                    "(lesson 7)",
                    kUsage, false, runPyramid);

}  // namespace ps
