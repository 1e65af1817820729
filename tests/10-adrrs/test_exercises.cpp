// Lesson 10, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 10.E1).
// The student's closed form against the variance of n / q computed from n's distribution
// (Eq. 10.4) summed over its two values.
#include <doctest/doctest.h>
#include <cmath>
#include <initializer_list>
#include "10-adrrs/exercises.h"

TEST_CASE("exercise: the variance that survival and splitting add (Eq. 10.E1) [1 pt]") {
    for (const double q : {0.05, 0.3, 0.5, 1.0, 1.25, 2.5, 3.9, 7.0}) {
        const double lo = std::floor(q), p = q - lo;  // P(n = lo + 1) = p
        const double mean = ((1.0 - p) * lo + p * (lo + 1.0)) / q;
        const double second = ((1.0 - p) * lo * lo + p * (lo + 1.0) * (lo + 1.0)) / (q * q);
        const double expected = second - mean * mean, got = ps::splitVariance(q);
        CHECK_MESSAGE(std::abs(got - expected) <= 1e-9 + 1e-9 * std::abs(expected),
                      "splitVariance(q " << q << "): expected " << expected
                                         << " (the variance of n / q over n's two values), got " << got);
    }
}
