// Lesson 11, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 11.E1).
// The student's closed form against the definition of the form factor, the integral over the disk
// of cos(theta_x) cos(theta_y) / (pi r^2) (the inner integral of Eq. 11.22), evaluated by
// quadrature: points y of the disk in polar coordinates, the cosines and r from the vectors.
#include <doctest/doctest.h>
#include <cmath>
#include <utility>
#include "11-classics/exercises.h"

namespace {

// The form factor from the point x = 0 with normal +z to the disk of radius R in the plane z = h,
// centred on the z axis, facing down (normal -z): composite Simpson's rule in the radius (n
// panels), the midpoint rule in the angle (m points).
double diskFormFactorByQuadrature(double R, double h) {
    const double pi = 3.14159265358979323846;
    const int n = 4000, m = 16;
    auto ring = [&](double rho) {  // the integrand integrated over the angle at radius rho, times rho
        double sum = 0.0;
        for (int k = 0; k < m; ++k) {
            const double phi = 2.0 * pi * (k + 0.5) / m;
            const double y[3] = {rho * std::cos(phi), rho * std::sin(phi), h};  // the point on the disk
            const double r2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2], r = std::sqrt(r2);
            const double cosX = y[2] / r;  // n_x = (0, 0, 1), towards y
            const double cosY = y[2] / r;  // n_y = (0, 0, -1), towards x = -y
            sum += cosX * cosY / (pi * r2);
        }
        return sum * (2.0 * pi / m) * rho;
    };
    const double step = R / n;
    double s = ring(0.0) + ring(R);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * ring(i * step);
    return s * step / 3.0;
}

}  // namespace

TEST_CASE("exercise: the form factor from a point to a parallel coaxial disk (Eq. 11.E1) [1 pt]") {
    const std::pair<double, double> cases[] = {{1.0, 1.0},  {0.5, 2.0},  {2.0, 0.5}, {1.0, 0.05},
                                               {0.01, 1.0}, {30.0, 1.0}, {3.0, 4.0}};
    for (const std::pair<double, double>& c : cases) {
        const double R = c.first, h = c.second;  // named, not bound: clang < 16 captures no binding in a lambda
        const double expected = diskFormFactorByQuadrature(R, h), got = ps::diskFormFactor(R, h);
        CHECK_MESSAGE(std::abs(got - expected) <= 1e-6 * expected,
                      "diskFormFactor(R " << R << ", h " << h << "): expected " << expected
                                          << " (the integral of cos theta_x cos theta_y / (pi r^2) over the disk, "
                                             "by quadrature), got "
                                          << got);
    }
}
