// Lesson 2, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 2.E1).
// The student's closed form for the solid angle of a sphere against an independent evaluation:
// the visible part of the sphere's surface, converted to solid angle by Eq. 2.3
// (d omega = cos(theta_y) dA / d^2), integrated numerically (Simpson's rule, double).
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include "02-direct-mis/exercises.h"

namespace {

// The viewer at the origin, the sphere's centre at (0, 0, d). A point of the sphere at angle beta
// from the centre's direction back to the viewer: y = c + r (sin b, 0, -cos b) rotated by phi,
// visible while cos(theta_y) > 0, i.e. beta < acos(r / d); dA = r^2 sin(beta) d(beta) d(phi).
double sphereSolidAngleNumeric(double r, double d, int m) {
    const double pi = 3.14159265358979323846, betaMax = std::acos(r / d), h = betaMax / m;
    auto g = [&](double b) {
        const double yx = r * std::sin(b), yz = d - r * std::cos(b);  // y (phi = 0)
        const double nx = std::sin(b), nz = -std::cos(b);             // normal at y
        const double dist2 = yx * yx + yz * yz, dist = std::sqrt(dist2);
        const double cosY = std::max(0.0, -(nx * yx + nz * yz) / dist);  // towards the viewer
        return cosY / dist2 * r * r * std::sin(b);
    };
    double sum = g(0.0) + g(betaMax);
    for (int i = 1; i < m; ++i) sum += (i % 2 ? 4.0 : 2.0) * g(i * h);
    return 2.0 * pi * sum * h / 3.0;
}

}  // namespace

TEST_CASE("exercise: the solid angle of a sphere, from close by to far away (Eq. 2.E1) [1 pt]") {
    const double cases[][2] = {{1.0, 1.01}, {1.0, 2.0}, {0.3, 10.0}, {1e-3, 1.0}, {1e-6, 10.0}};
    for (const auto& c : cases) {
        const double expected = sphereSolidAngleNumeric(c[0], c[1], 20000);
        const double got = ps::sphereSolidAngle(c[0], c[1]);
        CHECK_MESSAGE(std::abs(got / expected - 1.0) < 1e-6,
                      "sphereSolidAngle(radius "
                          << c[0] << ", distance " << c[1] << "): expected " << expected
                          << " sr (numerical integral over the visible cap), got " << got << " (ratio "
                          << got / expected << "; far away it must approach pi r^2 / d^2 = "
                          << 3.14159265358979 * c[0] * c[0] / (c[1] * c[1])
                          << (got > 0.0 && c[0] / c[1] < 1e-4
                                  ? "; off only for small r / d: cancellation in 1 - cos theta_max)"
                                  : ")"));
    }
}
