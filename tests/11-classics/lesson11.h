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
// m = 16 statistical tests, each at the level alpha() = testalpha::perTest(m) (tests/support/alpha.h
// derives it from the course's 1 %: a correct implementation fails the whole graded suite by
// bad luck in fewer than 1 run in 100).
constexpr int kStatisticalTestsPaths = 1, kStatisticalTestsLens = 8, kStatisticalTestsRadiosity = 7;
constexpr int kStatisticalTests = kStatisticalTestsPaths + kStatisticalTestsLens + kStatisticalTestsRadiosity;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }

}  // namespace lesson11
