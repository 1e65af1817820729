// image_compare: one image against a reference, as `pathspace converge` measures error
// (framework/metrics.h: MSE, relMSE, relMSE without its largest 0.1 % of terms), plus each
// image's mean colour. For images of the same scene from another renderer (bench/README.md,
// "Renders against SmallVCM"): equal means say the scene was transcribed right, the relMSE says
// how noisy each renderer's image is at equal time. Reads .pfm or .hdr (RGBE, 1 % precision).
// With --scene, the pixels in which a point light of the scene is seen directly are left out of
// the means and the error, as converge does: one such pixel can hold half the image's energy,
// and only some algorithms render it. A benchmark tool, never a test.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>
#include "report/converge.h"
#include "errors.h"
#include "image.h"
#include "metrics.h"
#include "scene_loader.h"

namespace {

ps::Color mean(const ps::Image& img, const std::vector<bool>& leftOut) {
    double s[3] = {0.0, 0.0, 0.0}, n = 0.0;
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        if (!leftOut.empty() && leftOut[i]) continue;
        for (int k = 0; k < 3; ++k) s[k] += img.pixels[i][k];
        n += 1.0;
    }
    return ps::Color(float(s[0] / n), float(s[1] / n), float(s[2] / n));
}

}  // namespace

int main(int argc, char** argv) {
    const bool help = argc == 2 && !std::strcmp(argv[1], "--help");
    const bool withScene = argc == 5 && !std::strcmp(argv[3], "--scene");
    if (help || (argc != 3 && !withScene)) {
        std::fprintf(
            help ? stdout : stderr,
            "usage: image_compare IMAGE REFERENCE [--scene FILE]\n"
            "Prints the mean colour of both (.pfm or .hdr) and IMAGE's MSE, relMSE and trimmed relMSE\n"
            "against REFERENCE, as pathspace converge computes them (framework/metrics.h). With --scene,\n"
            "the pixels in which one of the scene's point lights is seen directly are left out, as in converge.\n");
        return help ? 0 : 2;
    }
    try {
        // The reference must have the image's size: compared from its header, before its pixels.
        const ps::Image img = ps::readImage(argv[1]), ref = ps::readImage(argv[2], img.width, img.height);
        std::vector<bool> leftOut;
        if (withScene) {
            const ps::Scene scene = ps::loadScene(argv[4]);
            const std::vector<ps::PointLightPixel> pixels = ps::pointLightsInView(scene);
            for (const ps::PointLightPixel& p : pixels) std::printf("left out: %s\n", ps::describe(p).c_str());
            leftOut = ps::leftOutMask(scene, pixels);
            if (!leftOut.empty() && leftOut.size() != ref.pixels.size())
                throw ps::InputError(std::string(argv[4]) + ": its resolution is not the images'");
        }
        const ps::ErrorMetrics e = ps::computeError(img, ref, leftOut);
        const ps::Color mi = mean(img, leftOut), mr = mean(ref, leftOut);
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
