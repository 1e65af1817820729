// pathspace compare A B [options]: how image A differs from image B (B the reference), and where:
// relMSE, the mean difference and, with variance images, its z-score and a per-pixel z-test, and
// a false-colour picture of the difference (report/compare.h has the definitions). A failed image
// test of the lessons writes its two images and prints the compare command to run on them.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include "command.h"
#include "errors.h"
#include "image.h"
#include "report/compare.h"

namespace ps {
namespace {

const char* const kUsage = R"(compare options:
  A, B               the two images (.pfm or .hdr; PFM is exact); B is the reference of relMSE
  --variance-a FILE  the variance of A's pixel means (.pfm, as `render --variance` writes it)
  --variance-b FILE  the same for B; with either, the mean difference gets its z-score and every
                     pixel channel z = (a - b) / sqrt(varA + varB), tested as the graded tests do
  --alpha P          the per-pixel test's level over all channels (Sidak; default 0.01)
  --scale S          the false colour is full at |z| = S (default 5), or without variances at
                     |a - b| / sqrt(b^2 + 0.01) = S (default: its 99th percentile)
  --out FILE.png     the false-colour difference (default compare.png): black where A and B
                     agree, red where A is brighter, blue where A is darker; the signed scores
                     (z, or the relative error) go to FILE.pfm beside it
)";

struct CompareOptions {
    std::string a, b, varianceA, varianceB, out = "compare.png";
    double alpha = 0.01, scale = 0.0;
};

CompareOptions parseCompareOptions(const std::vector<std::string>& args) {
    CompareOptions o;
    std::vector<std::string> images;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::string { return optionValue(args, i); };
        if (a == "--variance-a") o.varianceA = value();
        else if (a == "--variance-b") o.varianceB = value();
        else if (a == "--alpha") o.alpha = parseWithin<double>(a, value(), 1e-12, 0.5);
        else if (a == "--scale") o.scale = parsePositive(a, value());
        else if (a == "--out") o.out = value();
        else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "'");
        else images.push_back(a);
    }
    if (images.size() != 2) throw UsageError("'compare' takes two images, A and B");
    o.a = images[0];
    o.b = images[1];
    // Every file this run writes, checked before an image is read (command.h); no input is ever
    // overwritten by an output.
    const std::string pfm = stem(o.out) + ".pfm";
    std::vector<InputFile> inputs = {{"image A", o.a, ""}, {"image B", o.b, ""}};
    if (!o.varianceA.empty()) inputs.push_back({"the variance of A", o.varianceA, "--variance-a"});
    if (!o.varianceB.empty()) inputs.push_back({"the variance of B", o.varianceB, "--variance-b"});
    checkOutputFiles({{"--out", o.out, {".png"}}, {"--out", pfm, {".pfm"}}}, inputs);
    return o;
}

std::string number(double v) {
    std::ostringstream os;
    os << std::setprecision(4) << v;
    return os.str();
}

std::string colorText(const Color& c) { return number(c.r) + " " + number(c.g) + " " + number(c.b); }

int runCompare(const CompareOptions& o) {
    // B and the variances must have A's size: compared from their headers, before their pixels.
    const Image a = readImage(o.a), b = readImage(o.b, a.width, a.height);
    Image va, vb;
    if (!o.varianceA.empty()) va = readImage(o.varianceA, a.width, a.height);
    if (!o.varianceB.empty()) vb = readImage(o.varianceB, a.width, a.height);
    const ImageComparison c = compareImages(a, b, &va, &vb, o.alpha);

    std::cout << "A: " << o.a << " (" << c.width << "x" << c.height << "), mean r g b " << colorText(c.meanA) << "\n"
              << "B: " << o.b << ", mean r g b " << colorText(c.meanB) << "\n";
    if (c.nonFiniteA || c.nonFiniteB)
        std::cout << "NaN or Inf: " << c.nonFiniteA << " pixels of A, " << c.nonFiniteB
                  << " of B (left out of every number below)\n";
    std::cout << "relMSE " << number(c.error.relMse) << " (without the largest 0.1 %: " << number(c.error.relMseTrimmed)
              << "), MSE " << number(c.error.mse) << "   [mean of (a - b)^2 / (b^2 + 0.01)]\n";
    const double meanB = (double(c.meanB.r) + c.meanB.g + c.meanB.b) / 3.0;
    std::cout << "mean difference A - B: " << number(c.meanDifference);
    if (meanB != 0.0) std::cout << " (" << number(100.0 * c.meanDifference / meanB) << " % of B's mean)";
    if (c.hasVariance) {
        const bool differs = std::abs(c.meanZ) > 3.3;  // two-sided p < 0.001
        std::cout << ", standard error " << number(c.meanDifferenceError) << ", z = " << number(c.meanZ) << ":\n  "
                  << (differs ? (c.meanZ > 0 ? "A is brighter than B" : "A is darker than B")
                              : "A and B have the same mean")
                  << (differs ? " beyond their noise" : " within their noise")
                  << " (|z| > 3.3 happens by chance once in 1000;\n  the channels of a pixel are taken as "
                     "fully correlated, so |z| is not overstated)\n";
        std::cout << "per pixel: " << c.beyondThreshold << " of " << c.channels << " channels have |z| > "
                  << number(c.zThreshold) << "\n  (level " << o.alpha
                  << " over all channels; a graded image test passes with 99.75 % of them within)\n";
    } else {
        std::cout << "\n  (give --variance-a / --variance-b for its z-score and a per-pixel test)\n";
    }
    static const char* const kChannel[3] = {"r", "g", "b"};
    if (!c.largest.empty() && c.largest[0].score != 0.0) {
        std::cout << "largest differences (" << (c.hasVariance ? "z" : "(a - b) / sqrt(b^2 + 0.01)") << "):\n";
        for (const ChannelDifference& d : c.largest) {
            if (d.score == 0.0) break;
            std::cout << "  pixel (" << d.x << ", " << d.y << ") " << kChannel[d.channel] << ": A " << number(d.a)
                      << ", B " << number(d.b) << ", " << (c.hasVariance ? "z " : "") << number(d.score) << "\n";
        }
    }
    double scaleUsed = 0.0;
    writePNG(o.out, differenceImage(a, b, &va, &vb, o.scale, scaleUsed));
    const std::string pfm = stem(o.out) + ".pfm";
    writePFM(pfm, scoreImage(a, b, &va, &vb));
    std::cout << "wrote " << o.out << " (red: A brighter, blue: A darker; full colour at "
              << (c.hasVariance ? "|z| " : "relative error ") << number(scaleUsed)
              << (c.hasVariance ? ", black below |z| 1" : "") << ") and " << pfm << " (the signed "
              << (c.hasVariance ? "z" : "relative error") << " of every channel)\n";
    return 0;
}

int runCompareCommand(const std::vector<std::string>& args) { return runCompare(parseCompareOptions(args)); }

Command compareCommand() {
    Command c;
    c.name = "compare";
    c.order = 25;
    c.synopsis = "compare A B [options]";
    c.summary = "how image A differs from B: relMSE, mean difference, z-scores, where";
    c.usage = kUsage;
    c.run = runCompareCommand;
    return c;
}

}  // namespace

PS_REGISTER_COMMAND(compareCommand());

}  // namespace ps
