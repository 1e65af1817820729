// Lesson 12, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 12.E1).
// The student's closed form against E[X^2] / E[X]^2 - 1 integrated numerically over the hemisphere
// (a 2000-point midpoint rule in cos(theta); the integrand is smooth).
#include <doctest/doctest.h>
#include <cmath>
#include <initializer_list>
#include "12-path-guiding/exercises.h"

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST_CASE("exercise: the variance of a guided mixture under a uniform sky (Eq. 12.E1) [1 pt]") {
    for (const double alpha : {0.0, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0}) {
        // X = L mu / p with p = alpha / (2 pi) + (1 - alpha) mu / pi; E[X] = pi L;
        // E[X^2] = 2 pi int_0^1 L^2 mu^2 / p dmu.
        constexpr int N = 2000;
        double second = 0.0;
        for (int i = 0; i < N; ++i) {
            const double mu = (i + 0.5) / N, p = alpha / (2.0 * kPi) + (1.0 - alpha) * mu / kPi;
            second += mu * mu / p / N;
        }
        second *= 2.0 * kPi;
        const double expected = second / (kPi * kPi) - 1.0, got = ps::guidedVariance(alpha);
        CHECK_MESSAGE(std::abs(got - expected) <= 1e-5,
                      "guidedVariance(alpha " << alpha << "): expected " << expected
                                              << " (E[X^2] / E[X]^2 - 1 integrated over the hemisphere), got " << got);
    }
}
