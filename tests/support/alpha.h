// The significance level of the whole course's graded suite, and each lesson's share of it.
// A correct submission must fail the WHOLE graded suite (every lesson, every statistical test)
// by bad luck in fewer than 1 run in 100: alpha = 0.01 for the suite. Each of the kLessons lessons
// gets the Sidak share 1 - (1 - 0.01)^(1/13) ~ 7.73e-4, and a lesson with m statistical tests runs
// each at sidak(lessonFamily(), m), so the product of the pass probabilities over the whole suite
// is 0.99, however many tests each lesson has. scripts/seeds.sh measures the rate.
#pragma once
#include "statistics.h"

namespace ps::testalpha {

constexpr double kSuite = 0.01;  // false failure of the whole graded suite
constexpr int kLessons = 13;     // lessons 0-12 (a lesson without statistical tests wastes its share)

// The family-wise level of one lesson's statistical tests.
inline double lessonFamily() { return ps::stats::sidak(kSuite, kLessons); }

// The level of each of a lesson's m statistical tests.
inline double perTest(int m) { return ps::stats::sidak(lessonFamily(), m); }

}  // namespace ps::testalpha
