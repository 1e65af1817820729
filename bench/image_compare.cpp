// image_compare: one image against a reference, as `pathspace converge` measures error
// (framework/metrics.h: MSE, relMSE, relMSE without its largest 0.1 % of terms), plus each
// image's mean colour. For images of the same scene from another renderer (bench/README.md,
// "Renders against SmallVCM"): equal means say the scene was transcribed right, the relMSE says
// how noisy each renderer's image is at equal time. Reads .pfm or .hdr (RGBE, 1 % precision).
// A benchmark tool, never a test.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include "errors.h"
#include "image.h"
#include "metrics.h"

namespace {

ps::Color mean(const ps::Image& img) {
    double s[3] = {0.0, 0.0, 0.0};
    for (const ps::Color& c : img.pixels)
        for (int k = 0; k < 3; ++k) s[k] += c[k];
    const double n = double(img.pixels.size());
    return ps::Color(float(s[0] / n), float(s[1] / n), float(s[2] / n));
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 || !std::strcmp(argv[1], "--help")) {
        std::fprintf(argc == 2 ? stdout : stderr,
                     "usage: image_compare IMAGE REFERENCE\n"
                     "Prints the mean colour of both (.pfm or .hdr) and IMAGE's MSE, relMSE and trimmed relMSE\n"
                     "against REFERENCE, as pathspace converge computes them (framework/metrics.h).\n");
        return argc == 2 ? 0 : 2;
    }
    try {
        const ps::Image img = ps::readImage(argv[1]), ref = ps::readImage(argv[2]);
        const ps::ErrorMetrics e = ps::computeError(img, ref);
        const ps::Color mi = mean(img), mr = mean(ref);
        std::printf("image      %s: %d x %d, mean %.5f %.5f %.5f\n", argv[1], img.width, img.height, mi.r, mi.g, mi.b);
        std::printf("reference  %s: %d x %d, mean %.5f %.5f %.5f\n", argv[2], ref.width, ref.height, mr.r, mr.g, mr.b);
        std::printf("mean ratio %.4f %.4f %.4f\n", mi.r / mr.r, mi.g / mr.g, mi.b / mr.b);
        std::printf("MSE %.6g  relMSE %.6g  relMSE trimmed %.6g\n", e.mse, e.relMse, e.relMseTrimmed);
        return 0;
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "image_compare: %s\n", ex.what());
        return 1;
    }
}
