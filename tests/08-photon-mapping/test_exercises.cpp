// Lesson 8, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 8.E1).
// The student's closed form against the mean of E over the disc minus E at its centre,
// integrated numerically here (polar midpoint rule, error below 1e-5 here; the check allows 1e-4).
#include <doctest/doctest.h>
#include <cmath>
#include "08-photon-mapping/exercises.h"
#include "vecmath.h"

TEST_CASE("exercise: the box filter's bias on a quadratic irradiance (Eq. 8.E1) [1 pt]") {
    struct Case {
        double gx, gy, a, b, c, r;
    };
    const Case cases[] = {{0, 0, 1, 0, 0, 1},
                          {0, 0, 0, 1, 0, 2},
                          {3, -2, 0.5, 0.3, 0.2, 0.3},
                          {1, 1, -2, 5, 4, 0.7},
                          {0, 0, 0, 0, 7, 1.5}};
    for (const Case& c : cases) {
        const int nr = 400, nt = 64;
        double mean = 0.0;
        for (int i = 0; i < nr; ++i)
            for (int j = 0; j < nt; ++j) {
                const double s = (i + 0.5) / nr * c.r, t = (j + 0.5) / nt * 2.0 * ps::kPi;
                const double u = s * std::cos(t), v = s * std::sin(t);
                const double dE = c.gx * u + c.gy * v + c.a * u * u + c.b * v * v + c.c * u * v;
                mean += dE * s;  // area element s ds dtheta
            }
        mean *= (c.r / nr) * (2.0 * ps::kPi / nt) / (ps::kPi * c.r * c.r);
        const double got = ps::boxFilterBias(c.gx, c.gy, c.a, c.b, c.c, c.r);
        CHECK_MESSAGE(std::abs(got - mean) <= 1e-4 * std::max(1.0, std::abs(mean)),
                      "boxFilterBias(gx " << c.gx << ", gy " << c.gy << ", a " << c.a << ", b " << c.b << ", c " << c.c
                                          << ", r " << c.r << "): expected " << mean << " (the mean of E over the disc "
                                          << "minus E at its centre), got " << got);
    }
}
