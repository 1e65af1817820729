// Error of an image against a reference (../shared/notes/testing.md):
//   MSE    = mean over pixels and channels of (x - r)^2
//   relMSE = mean of (x - r)^2 / (r^2 + eps), eps = 0.01
//   relMSE without the largest 0.1 % of its terms (reported beside relMSE, never instead).
#pragma once
#include "image.h"

namespace ps {

constexpr double kRelMseEpsilon = 0.01;

struct ErrorMetrics {
    double mse = 0.0, relMse = 0.0, relMseTrimmed = 0.0;
};

// Throws InputError if the sizes differ.
ErrorMetrics computeError(const Image& img, const Image& ref);

}  // namespace ps
