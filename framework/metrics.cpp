#include "metrics.h"
#include <algorithm>
#include "errors.h"

namespace ps {

ErrorMetrics computeError(const Image& img, const Image& ref, const std::vector<bool>& leftOut) {
    if (img.width != ref.width || img.height != ref.height)
        throw InputError("reference image is " + std::to_string(ref.width) + "x" + std::to_string(ref.height) +
                         " but the render is " + std::to_string(img.width) + "x" + std::to_string(img.height));
    ErrorMetrics m;
    std::vector<double> rel;
    rel.reserve(img.pixels.size() * 3);
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        if (i < leftOut.size() && leftOut[i]) continue;
        for (int k = 0; k < 3; ++k) {
            const double x = img.pixels[i][k], r = ref.pixels[i][k], d2 = (x - r) * (x - r);
            m.mse += d2;
            rel.push_back(d2 / (r * r + kRelMseEpsilon));
        }
    }
    const double n = static_cast<double>(rel.size());
    if (n == 0) return m;
    m.mse /= n;
    for (double v : rel) m.relMse += v;
    m.relMse /= n;
    // Drop the largest 0.1 % of the terms (at least none, at most all but one).
    const size_t drop = static_cast<size_t>(n * 0.001);
    const size_t keep = rel.size() - drop;
    std::nth_element(rel.begin(), rel.begin() + (keep - 1), rel.end());
    double s = 0.0;
    for (size_t i = 0; i < keep; ++i) s += rel[i];
    m.relMseTrimmed = s / double(keep);
    return m;
}

}  // namespace ps
