// pathspace compare's numbers and pictures (compare.h).
#include "compare.h"
#include <algorithm>
#include <cmath>
#include <string>
#include "errors.h"

namespace ps {

namespace {

bool given(const Image* v) { return v != nullptr && !v->pixels.empty(); }

std::string sizeText(const Image& im) { return std::to_string(im.width) + "x" + std::to_string(im.height); }

void checkSize(const Image& a, const Image& other, const char* what) {
    if (other.width != a.width || other.height != a.height)
        throw InputError(std::string(what) + " is " + sizeText(other) + " but A is " + sizeText(a));
}

double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }

// The signed score of channel c of pixel i: z with variances, else the relative error.
double channelScore(const Image& a, const Image& b, const Image* varA, const Image* varB, size_t i, int c) {
    const double va = a.pixels[i][c], vb = b.pixels[i][c];
    if (given(varA) || given(varB)) {
        const double var = (given(varA) ? finiteOr0(varA->pixels[i][c]) : 0.0) +
                           (given(varB) ? finiteOr0(varB->pixels[i][c]) : 0.0) + kCompareVarianceFloor;
        return (va - vb) / std::sqrt(var);
    }
    return (va - vb) / std::sqrt(vb * vb + kRelMseEpsilon);
}

bool finitePixel(const Color& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

}  // namespace

double normalQuantileTwoSided(double p) {
    // P(|Z| >= z) = erfc(z / sqrt 2) falls from 1 at z = 0; bisection to double precision.
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

ImageComparison compareImages(const Image& a, const Image& b, const Image* varA, const Image* varB, double alpha,
                              int largest) {
    checkSize(a, b, "B");
    if (given(varA)) checkSize(a, *varA, "the variance of A");
    if (given(varB)) checkSize(a, *varB, "the variance of B");
    ImageComparison r;
    r.width = a.width;
    r.height = a.height;
    r.hasVariance = given(varA) || given(varB);
    r.channels = int(a.pixels.size()) * 3;
    // Pixels where either image is not finite are left out of every number (and counted).
    std::vector<bool> leftOut(a.pixels.size(), false);
    double sumA[3] = {0, 0, 0}, sumB[3] = {0, 0, 0}, varSum = 0.0;
    int used = 0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        const bool okA = finitePixel(a.pixels[i]), okB = finitePixel(b.pixels[i]);
        r.nonFiniteA += !okA;
        r.nonFiniteB += !okB;
        if (!okA || !okB) {
            leftOut[i] = true;
            continue;
        }
        ++used;
        double sigma = 0.0;  // sigma_r + sigma_g + sigma_b of a - b: the channels taken as fully
                             // correlated, so the standard error below is an upper bound
        for (int c = 0; c < 3; ++c) {
            sumA[c] += a.pixels[i][c];
            sumB[c] += b.pixels[i][c];
            const double v = (given(varA) ? finiteOr0(varA->pixels[i][c]) : 0.0) +
                             (given(varB) ? finiteOr0(varB->pixels[i][c]) : 0.0);
            sigma += std::sqrt(std::max(v, 0.0));
        }
        varSum += sigma * sigma;
    }
    if (used == 0) return r;
    r.error = computeError(a, b, leftOut);
    for (int c = 0; c < 3; ++c) {
        r.meanA[c] = float(sumA[c] / used);
        r.meanB[c] = float(sumB[c] / used);
        r.meanDifference += (sumA[c] - sumB[c]) / (3.0 * used);
    }
    if (r.hasVariance) {
        // mean = (1 / 3P) sum over pixels of (r + g + b): Var = sum Var(r + g + b) / (3P)^2.
        r.meanDifferenceError = std::sqrt(varSum) / (3.0 * used);
        r.meanZ = r.meanDifferenceError > 0.0 ? r.meanDifference / r.meanDifferenceError
                  : r.meanDifference == 0.0   ? 0.0
                                              : (r.meanDifference > 0 ? 1.0 : -1.0) * HUGE_VAL;
        r.zThreshold = normalQuantileTwoSided(1.0 - std::pow(1.0 - alpha, 1.0 / std::max(r.channels, 1)));
    }
    std::vector<ChannelDifference> all;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
        if (leftOut[i]) continue;
        for (int c = 0; c < 3; ++c) {
            const double s = channelScore(a, b, varA, varB, i, c);
            if (r.hasVariance && std::abs(s) > r.zThreshold) ++r.beyondThreshold;
            all.push_back({int(i % size_t(a.width)), int(i / size_t(a.width)), c, a.pixels[i][c], b.pixels[i][c], s});
        }
    }
    const size_t k = std::min(all.size(), size_t(std::max(largest, 0)));
    // Largest |score| first; ties in pixel order, so the list does not depend on the sort.
    std::partial_sort(all.begin(), all.begin() + k, all.end(),
                      [](const ChannelDifference& p, const ChannelDifference& q) {
                          if (std::abs(p.score) != std::abs(q.score)) return std::abs(p.score) > std::abs(q.score);
                          return std::make_pair(std::make_pair(p.y, p.x), p.channel) <
                                 std::make_pair(std::make_pair(q.y, q.x), q.channel);
                      });
    r.largest.assign(all.begin(), all.begin() + k);
    return r;
}

Image scoreImage(const Image& a, const Image& b, const Image* varA, const Image* varB) {
    checkSize(a, b, "B");
    Image out(a.width, a.height);
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) out.pixels[i][c] = float(channelScore(a, b, varA, varB, i, c));
    return out;
}

Image differenceImage(const Image& a, const Image& b, const Image* varA, const Image* varB, double scale,
                      double& scaleUsed) {
    const Image s = scoreImage(a, b, varA, varB);
    const bool z = given(varA) || given(varB);
    // Per pixel, the channel with the largest |score| (NaN or Inf: shown as full white).
    std::vector<double> worst(s.pixels.size(), 0.0);
    std::vector<double> magnitudes;
    for (size_t i = 0; i < s.pixels.size(); ++i) {
        double w = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double v = s.pixels[i][c];
            if (!std::isfinite(v)) {
                w = HUGE_VAL;
                break;
            }
            if (std::abs(v) > std::abs(w)) w = v;
        }
        worst[i] = w;
        if (std::isfinite(w)) magnitudes.push_back(std::abs(w));
    }
    double lo = 0.0;  // |score| at or below it: black
    if (z) {
        lo = 1.0;
        scaleUsed = scale > 0.0 ? scale : 5.0;
    } else if (scale > 0.0) {
        scaleUsed = scale;
    } else {
        scaleUsed = 0.0;
        if (!magnitudes.empty()) {
            const size_t k = size_t(0.99 * double(magnitudes.size() - 1));
            std::nth_element(magnitudes.begin(), magnitudes.begin() + k, magnitudes.end());
            scaleUsed = magnitudes[k];
        }
        if (!(scaleUsed > 0.0)) scaleUsed = 1.0;  // the images are equal (almost) everywhere
    }
    Image out(a.width, a.height);
    for (size_t i = 0; i < worst.size(); ++i) {
        if (!std::isfinite(worst[i])) {
            out.pixels[i] = Color(1.0f);
            continue;
        }
        const double t = std::clamp((std::abs(worst[i]) - lo) / std::max(scaleUsed - lo, 1e-30), 0.0, 1.0);
        // Red to yellow for A brighter, blue to cyan for A darker: the hue says the sign, the
        // brightness how far.
        const float u = float(t), v = float(t * t);
        out.pixels[i] = worst[i] > 0 ? Color(u, 0.8f * v, 0.0f) : Color(0.0f, 0.8f * v, u);
    }
    return out;
}

}  // namespace ps
