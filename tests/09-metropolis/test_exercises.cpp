// Lesson 9, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 9.E1).
// The student's closed form against the flux of Eq. 9.3 across x = 1/2 integrated numerically
// (midpoint rule in both variables, 2000 x 2000 cells per direction).
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include "09-metropolis/exercises.h"

TEST_CASE("exercise: the rate at which local mutations cross x = 1/2 (Eq. 9.E1) [1 pt]") {
    for (const double r : {0.01, 0.05, 0.1, 0.2, 0.25}) {
        // Left to right: x in [1/2 - r, 1/2], y in [1/2, x + r], pi(x) = 12 (x - 1/2)^2,
        // T = 1 / (2r) (full windows), a = min(1, f(y) / f(x)); right to left is its mirror image.
        constexpr int n = 2000;
        double flux = 0.0;
        const double hx = r / n;
        for (int i = 0; i < n; ++i) {
            const double x = 0.5 - r + (i + 0.5) * hx, fx = (x - 0.5) * (x - 0.5);
            const double len = x + r - 0.5, hy = len / n;
            double inner = 0.0;
            for (int j = 0; j < n; ++j) {
                const double y = 0.5 + (j + 0.5) * hy, fy = (y - 0.5) * (y - 0.5);
                inner += std::min(fx, fy);
            }
            flux += 12.0 / (2.0 * r) * inner * hy * hx;
        }
        const double expected = 2.0 * flux, got = ps::crossingRate(r);
        CHECK_MESSAGE(std::abs(got - expected) <= 1e-4 * expected,
                      "crossingRate(r " << r << "): expected " << expected
                                        << " (both directions of the flux of Eq. 9.3 across 1/2), got " << got);
    }
}
