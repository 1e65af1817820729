// Lesson 1, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 1.E1).
// The student's closed form against the hemisphere integral done numerically (Simpson's rule in
// theta, in double): C(n) times the integral of cos^(n+1)(theta) must be 1.
#include <doctest/doctest.h>
#include <cmath>
#include <initializer_list>
#include "01-monte-carlo/exercises.h"

namespace {

// The integral of cos^(n+1)(theta) over the hemisphere: 2 pi times the integral over theta in
// [0, pi/2] of cos^(n+1) sin, by composite Simpson with m (even) intervals.
double cosPowerHemisphereIntegral(double n, int m) {
    const double pi = 3.14159265358979323846, h = 0.5 * pi / m;
    auto g = [&](double t) { return std::pow(std::cos(t), n + 1.0) * std::sin(t); };
    double sum = g(0.0) + g(0.5 * pi);
    for (int i = 1; i < m; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(i * h);
    return 2.0 * pi * sum * h / 3.0;
}

}  // namespace

TEST_CASE("exercise: the Phong BRDF's normalisation C(n) reflects everything at normal incidence (Eq. 1.E1) [1 pt]") {
    for (double n : {0.0, 1.0, 2.5, 10.0, 100.0, 10000.0}) {
        const double integral = cosPowerHemisphereIntegral(n, 200000);
        const double c = ps::phongBRDFNormalization(n);
        CHECK_MESSAGE(
            std::abs(c * integral - 1.0) < 1e-6,
            "phongBRDFNormalization("
                << n
                << "): expected C(n) with C(n) * (integral of cos^(n+1) over the "
                   "hemisphere = "
                << integral << ") = 1, i.e. C = " << 1.0 / integral << ", got " << c << " (ratio " << c * integral
                << (std::abs(c / ((n + 1.0) / (2.0 * 3.14159265358979323846)) - 1.0) < 1e-6
                        ? "; that is (n+1)/2pi, the sampling pdf's constant: the reflectance has one more cos theta)"
                        : ")"));
    }
}
