// Error of an image against a reference (../shared/notes/testing.md):
//   MSE    = mean over pixels and channels of (x - r)^2
//   relMSE = mean of (x - r)^2 / (r^2 + eps), eps = 0.01
//   relMSE without the largest 0.1 % of its terms (reported beside relMSE, never instead).
// A comparison may leave some pixels out (a point light seen directly, which some algorithms
// cannot sample: report/converge.h); the means are then over the other pixels.
#pragma once
#include <vector>
#include "image.h"

namespace ps {

constexpr double kRelMseEpsilon = 0.01;

struct ErrorMetrics {
    double mse = 0.0, relMse = 0.0, relMseTrimmed = 0.0;
};

// Throws InputError if the sizes differ. leftOut: per pixel, row by row, true for a pixel left
// out of the error (empty: none).
ErrorMetrics computeError(const Image& img, const Image& ref, const std::vector<bool>& leftOut = {});

}  // namespace ps
