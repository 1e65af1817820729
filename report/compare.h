// What `pathspace compare A B` computes: how image A differs from image B (B taken as the
// reference), in numbers and as a picture of where. The same numbers the graded image tests use:
//   relMSE = mean over pixels and channels of (a - b)^2 / (b^2 + 0.01)   (metrics.h)
//   mean difference = mean(a) - mean(b), over pixels and channels;
//   with variance images (the variance of each pixel's mean, `render --variance`), its z-score
//     z = (mean(a) - mean(b)) / sqrt(Var[mean(a)] + Var[mean(b)]), and per pixel channel
//     z = (a - b) / sqrt(varA + varB + floor)   (the per-pixel z-test of tests/support/statistics.h).
// NaN or Inf values are counted and left out of every mean.
#pragma once
#include <string>
#include <vector>
#include "image.h"
#include "metrics.h"

namespace ps {

// The per-pixel z of a channel: (a - b) / sqrt(varA + varB + kCompareVarianceFloor). The floor keeps
// a pixel that is exactly the same in both images (black, zero variance) at z = 0, as the tests do.
constexpr double kCompareVarianceFloor = 1e-8;

struct ChannelDifference {
    int x = 0, y = 0, channel = 0;  // channel 0, 1, 2 = r, g, b
    double a = 0.0, b = 0.0;
    double score = 0.0;  // the signed z with variances, else the signed relative error (a - b) / sqrt(b^2 + 0.01)
};

struct ImageComparison {
    int width = 0, height = 0;
    ErrorMetrics error;                // of A against B (B the reference)
    Color meanA, meanB;                // per channel, over the finite pixels
    double meanDifference = 0.0;       // mean(a) - mean(b) over pixels and channels
    bool hasVariance = false;          // a variance image was given for A or B
    double meanDifferenceError = 0.0;  // standard error of meanDifference (with variances)
    double meanZ = 0.0;                // meanDifference / meanDifferenceError (with variances)
    int channels = 0;                  // pixels x 3
    int nonFiniteA = 0, nonFiniteB = 0;
    double zThreshold = 0.0;                 // |z| beyond it fails the per-channel test at level sidak(alpha, channels)
    int beyondThreshold = 0;                 // channels with |z| > zThreshold (with variances)
    std::vector<ChannelDifference> largest;  // the largest |score| first
};

// Compares A with B. varA and varB may be null or empty images (no variance of that image); given,
// each must have A's size. alpha: the per-pixel test's family-wise level over all channels
// (Sidak), as in the graded tests. Throws InputError when the sizes differ (naming both).
ImageComparison compareImages(const Image& a, const Image& b, const Image* varA, const Image* varB, double alpha = 0.01,
                              int largest = 5);

// The false-colour picture of where A differs from B: black where they agree, red where A is
// brighter, blue where A is darker (the channel with the largest |score| of each pixel). With
// variances the colour is full at |z| >= zFull (default 5) and nothing below |z| 1; without, full
// at `scale` (the 99th percentile of |a - b| / sqrt(b^2 + 0.01) when scale <= 0; the value used is
// returned in `scaleUsed`).
Image differenceImage(const Image& a, const Image& b, const Image* varA, const Image* varB, double scale,
                      double& scaleUsed);

// The signed per-channel scores as an image (z with variances, else the relative error): what
// compare writes as PFM beside its PNG.
Image scoreImage(const Image& a, const Image& b, const Image* varA, const Image* varB);

// The standard normal's two-sided quantile: |z| with P(|Z| >= |z|) = p (0 < p < 1).
double normalQuantileTwoSided(double p);

}  // namespace ps
