// Lesson 6, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 6.E1).
// The student's p_{2,1} of a length-2 path against an independent evaluation: the probability
// that the light tracer's first ray from x0 (cosine-weighted) hits a tiny square patch around x1
// (perpendicular to n1), divided by the patch's area and by the light's area. The patch's solid
// angle is computed exactly from its corners (Van Oosterom and Strackee's triangle formula).
#include <doctest/doctest.h>
#include <cmath>
#include <initializer_list>
#include "06-path-space/exercises.h"

namespace {

struct D3 {
    double x, y, z;
};
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
D3 operator*(double s, D3 a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double len(D3 a) { return std::sqrt(dot(a, a)); }
D3 unit(D3 a) { return (1.0 / len(a)) * a; }
D3 of(const ps::Vec3& v) { return {v.x, v.y, v.z}; }

double triangleSolidAngle(D3 a, D3 b, D3 c) {  // seen from the origin
    const double num = std::abs(dot(a, cross(b, c)));
    const double den = len(a) * len(b) * len(c) + dot(a, b) * len(c) + dot(a, c) * len(b) + dot(b, c) * len(a);
    return 2.0 * std::atan2(num, den);
}

}  // namespace

TEST_CASE("exercise: the light tracer's pdf p_{2,1} of a length-2 path, by hand (Eq. 6.E1) [1 pt]") {
    using ps::Vec3;
    struct Case {
        double lightArea;
        Vec3 x0, n0, x1, n1;
    };
    const Case cases[] = {
        {0.25, Vec3(0, 2, 0), Vec3(0, -1, 0), Vec3(0, 0, 0), Vec3(0, 1, 0)},                 // straight down
        {1.0, Vec3(0.5f, 3, -1), Vec3(0, -1, 0), Vec3(2, 0, 1.5f), Vec3(0, 1, 0)},           // oblique
        {0.04, Vec3(0, 1, 0), Vec3(0.6f, -0.8f, 0), Vec3(1.5f, -1, 0.25f), Vec3(-1, 0, 0)},  // onto a wall
        {2.0, Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(3, 1, 0.5f), Vec3(0, 0, -1)},               // grazing: 1/d^2 small
    };
    const double pi = 3.14159265358979323846;
    for (const Case& c : cases) {
        const D3 x0 = of(c.x0), n0 = unit(of(c.n0)), x1 = of(c.x1), n1 = unit(of(c.n1));
        // A square patch of side h around x1 in the plane of n1, its corners relative to x0.
        const D3 t = unit(std::abs(n1.x) > 0.5 ? cross(n1, D3{0, 1, 0}) : cross(n1, D3{1, 0, 0})), b = cross(n1, t);
        const double h = 1e-4 * len(x1 - x0);
        const D3 p00 = x1 - x0 + (-h / 2) * t + (-h / 2) * b, p10 = x1 - x0 + (h / 2) * t + (-h / 2) * b;
        const D3 p11 = x1 - x0 + (h / 2) * t + (h / 2) * b, p01 = x1 - x0 + (-h / 2) * t + (h / 2) * b;
        const double omega = triangleSolidAngle(p00, p10, p11) + triangleSolidAngle(p00, p11, p01);
        const double cos0 = dot(n0, unit(x1 - x0));
        const double expected = (1.0 / c.lightArea) * (cos0 / pi) * omega / (h * h);  // P(hit patch) / area
        const double got = ps::lightTracerPdfK2(c.lightArea, c.x0, c.n0, c.x1, c.n1);
        CHECK_MESSAGE(std::abs(got / expected - 1.0) < 1e-4,
                      "lightTracerPdfK2(light area "
                          << c.lightArea << ", cos theta_0 " << cos0 << ", |cos theta_1| "
                          << std::abs(dot(n1, unit(x1 - x0))) << ", d " << len(x1 - x0) << "): expected " << expected
                          << " per unit area (per unit light area too), got " << got << " (ratio " << got / expected
                          << "; the cosine at x1 or the 1/d^2 of Eq. 6.6 missing, or 1/A of the light?)");
    }
    // x1 behind the light's plane: the cosine-weighted first ray never goes there, p = 0.
    const double behind = ps::lightTracerPdfK2(1.0, Vec3(0, 2, 0), Vec3(0, -1, 0), Vec3(0.5f, 3, 0), Vec3(0, -1, 0));
    CHECK_MESSAGE(behind == 0.0,
                  "lightTracerPdfK2 with x1 behind the light (cos theta_0 = -0.89): expected 0 (the "
                  "light emits only on its front side), got "
                      << behind);
}
