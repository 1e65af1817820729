// Lesson 3, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 3.E1).
// The student's closed form for the depth a furnace needs against the series of Eq. 3.8 summed
// term by term (double) until the relative truncation bias is at most eps.
#include <doctest/doctest.h>
#include <cmath>
#include <initializer_list>
#include "03-path-tracing/exercises.h"

TEST_CASE("exercise: the maximum depth that brings the furnace's truncation bias below eps (Eq. 3.E1) [1 pt]") {
    // Cases chosen so that no a^(D+1) lies within 1e-6 (relative) of eps.
    const double cases[][2] = {{0.5, 0.01}, {0.8, 0.016}, {0.99, 1e-3}, {0.999, 0.01},
                               {0.1, 0.5},  {0.0, 0.1},   {0.73, 0.2}};
    for (const auto& c : cases) {
        const double a = c[0], eps = c[1], lInf = 1.0 / (1.0 - a);
        double lD = 0.0, term = 1.0;
        int expected = -1;
        for (int D = 0; D < 100000; ++D, term *= a) {
            lD += term;  // L_D = sum_{k=0}^{D} a^k (Le = 1)
            if ((lInf - lD) / lInf <= eps) {
                expected = D;
                break;
            }
        }
        REQUIRE(expected >= 0);
        const int got = ps::furnaceDepthForBias(a, eps);
        CHECK_MESSAGE(got == expected,
                      "furnaceDepthForBias(albedo "
                          << a << ", eps " << eps << "): expected D = " << expected
                          << " (the partial sums of Eq. 3.8 reach relative bias <= eps there, not at D - 1), got "
                          << got
                          << (got == expected + 1   ? " (one too deep: the bias of depth D is a^(D+1), not a^D)"
                              : got == expected - 1 ? " (one too shallow: the bias of depth D is a^(D+1), not a^(D+2))"
                                                    : ""));
    }
}
