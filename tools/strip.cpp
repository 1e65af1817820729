// strip: PFM images side by side, each under its label, as one tone-mapped PNG (the same strip as
// `pathspace converge` writes; lesson 11's figures of one scene split by path expression).
//   ./build/strip OUT.png [--exposure E] LABEL=IMAGE.pfm ...
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>
#include "errors.h"
#include "image.h"
#include "report/label.h"

int main(int argc, char** argv) {
    if (argc < 3) {
        std::cerr << "usage: strip OUT.png [--exposure E] LABEL=IMAGE.pfm ...\n";
        return 2;
    }
    float exposure = 0.0f;
    std::vector<ps::Image> images;
    std::vector<std::string> labels;
    try {
        for (int i = 2; i < argc; ++i) {
            const std::string a = argv[i];
            if (a == "--exposure" && i + 1 < argc) {
                exposure = std::strtof(argv[++i], nullptr);
                continue;
            }
            const size_t eq = a.find('=');
            if (eq == std::string::npos) {
                std::cerr << "strip: '" << a << "' is not LABEL=IMAGE.pfm\n";
                return 2;
            }
            labels.push_back(a.substr(0, eq));
            images.push_back(ps::readImage(a.substr(eq + 1)));
        }
        ps::writePNG(argv[1], ps::labelledStrip(images, labels, ps::Color(std::exp2(-exposure))), exposure);
    } catch (const ps::InputError& e) {
        std::cerr << "strip: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
