// The significance level of the whole course's graded suite, and each lesson's share of it: the
// one place the graded tests' levels are derived (a lesson's test header says only how many
// statistical tests m it has). A correct submission must fail the WHOLE graded suite (every
// lesson, every statistical test) by bad luck in fewer than 1 run in 100: alpha = 0.01 for the
// suite. Each of the kLessons lessons gets the Sidak share a_L = 1 - (1 - 0.01)^(1/kLessons)
// (8.37e-4 with 12 lessons), and a lesson with m statistical tests runs each at
// alpha' = sidak(a_L, m) = 1 - (1 - a_L)^(1/m), so the product of the pass probabilities over the
// whole suite is 0.99, however many tests each lesson has. scripts/seeds.sh measures the rate.
#pragma once
#include "statistics.h"

namespace ps::testalpha {

constexpr double kSuite = 0.01;  // false failure of the whole graded suite
// The number of lesson folders (tests/support/CMakeLists.txt counts cmake/lessons.cmake's list for
// every test: a new lesson folder changes it; a lesson without statistical tests wastes its share).
#ifndef PATHSPACE_LESSON_COUNT
#error "PATHSPACE_LESSON_COUNT (the number of lesson folders) comes from tests/support/CMakeLists.txt"
#endif
constexpr int kLessons = PATHSPACE_LESSON_COUNT;

// The family-wise level of one lesson's statistical tests.
inline double lessonFamily() { return ps::stats::sidak(kSuite, kLessons); }

// The level of each of a lesson's m statistical tests.
inline double perTest(int m) { return ps::stats::sidak(lessonFamily(), m); }

}  // namespace ps::testalpha
