// Lesson 4, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 4.E1).
// The student's W_e of a pinhole with its image plane at distance f against an independent
// evaluation: a tiny square patch of the image plane holds the fraction (patch area) / A of the
// image, so integral over its solid angle of W_e cos(theta) must be that fraction (Eq. 4.5). The
// patch's solid angle is computed exactly from its corners (Van Oosterom and Strackee's triangle
// formula), not from a cosine power.
#include <doctest/doctest.h>
#include <cmath>
#include <initializer_list>
#include "04-measurement/exercises.h"

namespace {

struct D3 {
    double x, y, z;
};
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 cross(D3 a, D3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double len(D3 a) { return std::sqrt(dot(a, a)); }

// The solid angle of the triangle abc seen from the origin.
double triangleSolidAngle(D3 a, D3 b, D3 c) {
    const double la = len(a), lb = len(b), lc = len(c);
    const double num = std::abs(dot(a, cross(b, c)));
    const double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    return 2.0 * std::atan2(num, den);
}

}  // namespace

TEST_CASE("exercise: W_e of a pinhole whose image plane is at distance f (Eq. 4.E1) [1 pt]") {
    struct Case {
        double area, f, x, y;  // image area on the plane z = f, the patch's centre (x, y, f)
    };
    const Case cases[] = {{1.0, 1.0, 0.0, 0.0},
                          {0.5, 1.0, 0.3, -0.2},
                          {8.6e-4, 0.035, 0.012, 0.009},
                          {1200.0, 20.0, -15.0, 11.0},
                          {4.0, 2.0, 1.9, 1.9}};
    for (const Case& c : cases) {
        const double h = 1e-4 * c.f;  // the patch's side
        const D3 p00{c.x - h / 2, c.y - h / 2, c.f}, p10{c.x + h / 2, c.y - h / 2, c.f};
        const D3 p11{c.x + h / 2, c.y + h / 2, c.f}, p01{c.x - h / 2, c.y + h / 2, c.f};
        const double omega = triangleSolidAngle(p00, p10, p11) + triangleSolidAngle(p00, p11, p01);
        const double cosTheta = c.f / std::sqrt(c.x * c.x + c.y * c.y + c.f * c.f);
        const double expected = (h * h / c.area) / (omega * cosTheta);  // W_e cos(theta) omega = h^2 / A
        const double got = ps::pinholeImportance(c.area, c.f, cosTheta);
        CHECK_MESSAGE(
            std::abs(got / expected - 1.0) < 1e-5,
            "pinholeImportance(A "
                << c.area << ", f " << c.f << ", cos theta " << cosTheta << "): expected " << expected
                << " (a patch of the image plane of area a must get W_e cos theta d omega = a / A), got " << got
                << " (ratio " << got / expected << "; a ratio of 1/f^2 = " << 1.0 / (c.f * c.f)
                << " is the plane at distance 1; a power of cos theta off shows as a ratio that changes with theta)");
    }
}
