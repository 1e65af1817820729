// Lesson 11's significance level, shared by its three parts (paths_support.h, lens_support.h,
// radiosity_support.h): every statistical test of the lesson runs at the same Sidak level.
#pragma once
#include "alpha.h"

namespace lesson11 {

// The lesson's statistical tests, by part (each part's header lists its own):
//   paths (Whitted against pt filtered to its expression)                 1
//   lens (pt, lt, bpt through the lens; t = 0 against s = 0; drt against
//         pt, direct light and pt filtered to its expression; pt through
//         the lens against the pinhole on a plane in focus)              8
//   radiosity (form factors against closed forms; sums to 1)              7
// m = 16; each runs at alpha' = 1 - (1 - a_L)^(1/16) ~ 5.2e-5, where a_L = 1 - 0.99^(1/12) ~ 8.37e-4
// is this lesson's share of the whole graded suite's 1 % (tests/support/alpha.h).
constexpr int kStatisticalTestsPaths = 1, kStatisticalTestsLens = 8, kStatisticalTestsRadiosity = 7;
constexpr int kStatisticalTests = kStatisticalTestsPaths + kStatisticalTestsLens + kStatisticalTestsRadiosity;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

}  // namespace lesson11
