// Lesson 7, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 7.E1).
// The student's weight of technique s against Eq. 7.5 evaluated in long double (wider range than
// double, so the test's own p^b neither overflows nor underflows here), and the three weights
// must sum to 1.
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include "07-bidirectional/exercises.h"

TEST_CASE("exercise: the MIS weights of the three techniques of a length-2 path (Eq. 7.E1) [1 pt]") {
    struct Case {
        double pdf[3];
        double b;
    };
    const Case cases[] = {
        {{1.0, 2.0, 3.0}, 1.0},          {{1.0, 2.0, 3.0}, 2.0},      {{0.0, 5e-3, 2.0}, 2.0},  // s = 0 impossible
        {{4.0, 0.0, 0.0}, 1.0},          {{1e200, 1e-200, 1.0}, 2.0},                           // p^2 overflows double
        {{1e-200, 1e-210, 3e-205}, 2.0}, {{0.7, 0.7, 0.7}, 2.0},                                // p^2 underflows double
    };
    for (const Case& c : cases) {
        long double sum = 0.0L;
        for (double p : c.pdf) sum += std::pow((long double)p, (long double)c.b);
        double total = 0.0;
        for (int s = 0; s < 3; ++s) {
            const double expected = double(std::pow((long double)c.pdf[s], (long double)c.b) / sum);
            const double got = ps::techniqueWeightK2(c.pdf, s, c.b);
            total += got;
            CHECK_MESSAGE(
                std::abs(got - expected) <= 1e-9 * std::max(1.0, expected),
                "techniqueWeightK2(pdfs "
                    << c.pdf[0] << ", " << c.pdf[1] << ", " << c.pdf[2] << ", s = " << s << ", b = " << c.b
                    << "): expected " << expected << ", got " << got
                    << (std::isfinite(got) ? "" : " (p^b overflowed or underflowed: divide by the largest pdf first)"));
        }
        CHECK_MESSAGE(std::abs(total - 1.0) < 1e-9, "the three weights of pdfs " << c.pdf[0] << ", " << c.pdf[1] << ", "
                                                                                 << c.pdf[2] << " (b = " << c.b
                                                                                 << ") sum to " << total << ", not 1");
    }
}
