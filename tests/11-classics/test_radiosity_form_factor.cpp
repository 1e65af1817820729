// Lesson 11, graded: form factors by ray casting (Eq. 11.22-11.26): the point form factor by
// hand; formFactor against the closed forms of two directly opposed squares and two perpendicular
// squares with a common edge (each closed form checked first against a numerical integration of
// the definition); reciprocity for rectangles of different areas; a blocked pair; and
// sum_j F_ij = 1 in a closed box. Each t-test runs at alpha() (radiosity_support.h) with a power
// check: the standard error below 1 % of the value.
#include "radiosity_support.h"

using namespace lesson11radiosity;

namespace {

void checkFormFactor(const char* what, const ps::Scene& scene, int i, int j, double expected, int n, int samples,
                     uint64_t seed) {
    const ps::ElementMesh mesh(scene, 1, 1);
    const ps::stats::Welford w = independentEstimates(scene, mesh, i, j, n, samples, ps::testseed::seed(seed));
    const ps::stats::TTestResult t = ps::stats::tTest(w, expected, alpha(), 0.01);
    CHECK_MESSAGE(t.passed, "formFactor " << what << ": expected the closed form " << num(expected)
                                          << " (Eq. 11.22), got the mean of " << n << " estimates of " << samples
                                          << " samples " << num(w.mean) << " (ratio " << num(w.mean / expected)
                                          << ": pi would be a missing 1/pi, other factors a missing cosine or "
                                             "the wrong area)\n  "
                                          << t.report);
}

}  // namespace

TEST_CASE("radiosity: the point form factor g = A cos cos / (pi r^2), by hand (Eq. 11.23) [1 pt]") {
    struct Case {
        Vec3 x, nx, y, ny;
        float area;
        double expected;
        const char* what;
    };
    const float s = std::sqrt(0.5f);
    const Case cases[] = {
        {{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, -1}, 0.5f, 0.5 / (ps::kPi * 4.0), "facing each other at distance 2"},
        {{0, 0, 0},
         {0, 0, 1},
         {1, 0, 1},
         {-1, 0, 0},
         0.3f,
         0.3 * 0.5 / (ps::kPi * 2.0),
         "both cosines 1/sqrt(2), r^2 = 2"},
        {{1, 2, 3},
         {0, 0, 1},
         {1, 2 + 3 * s, 3 + 3 * s},
         {0, 0, -1},
         2.0f,
         2.0 * 0.5 / (ps::kPi * 9.0),
         "both cosines 1/sqrt(2), r = 3"},
        {{0, 0, 0},
         {0, 0, 1},
         {0, 0.5f, 2},
         {0, 0, -1},
         1.0f,
         1.0 * (2 / std::sqrt(4.25)) * (2 / std::sqrt(4.25)) / (ps::kPi * 4.25),
         "cos = 2 / sqrt(4.25) at both ends"},
        {{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 1}, 0.5f, 0.0, "y faces away from x"},
        {{0, 0, 0}, {0, 0, -1}, {0, 0, 2}, {0, 0, -1}, 0.5f, 0.0, "x faces away from y"},
        {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, 0.5f, 0.0, "y in x's plane (cos = 0)"},
        {{0, 0, 0}, {0, 0, 1}, {0, 0, 0}, {0, 0, -1}, 0.5f, 0.0, "x = y (r = 0)"},
    };
    for (const Case& c : cases) {
        const float g = ps::pointFormFactor(c.x, c.nx, c.y, c.ny, c.area);
        CHECK_MESSAGE(std::abs(double(g) - c.expected) <= 1e-5 * c.expected + 1e-9,
                      "pointFormFactor(x " << str(c.x) << ", n_x " << str(c.nx) << ", y " << str(c.y) << ", n_y "
                                           << str(c.ny) << ", area " << c.area << ") [" << c.what
                                           << "]: expected A cos+ cos+ / (pi r^2) = " << num(c.expected, 9) << ", got "
                                           << num(g, 9));
    }
}

TEST_CASE(
    "radiosity: F between two directly opposed unit squares at distance 1 equals Howell's closed form 0.1998 (t-test, Eq. 11.22, 11.26) [2 pts]") {
    const double closed = opposedRectangles(1, 1, 1), numeric = opposedRectanglesNumeric(1, 1, 1);
    REQUIRE_MESSAGE(std::abs(closed - numeric) < 1e-6,
                    "the test's oracle: closed form " << closed << " against the definition integrated " << numeric);
    REQUIRE(std::abs(closed - 0.199825) < 1e-6);
    checkFormFactor("from a unit square to the opposed one at distance 1", opposedSquares(1.0), 0, 1, closed, 8192, 4,
                    1101);
    // Closer, where the cosines and 1/r^2 vary more over the squares: c = 0.25.
    const double close = opposedRectangles(1, 1, 0.25);
    REQUIRE(std::abs(close - opposedRectanglesNumeric(1, 1, 0.25, 24)) < 1e-5);
    checkFormFactor("from a unit square to the opposed one at distance 0.25", opposedSquares(0.25), 1, 0, close, 8192,
                    4, 1102);
}

TEST_CASE(
    "radiosity: F between perpendicular unit squares with a common edge equals the closed form 0.2000, each sample at most 2 (t-test, Eq. 11.25, 11.26) [2 pts]") {
    const double closed = perpendicularRectangles(1, 1, 1), numeric = perpendicularRectanglesNumeric(1, 1, 1);
    REQUIRE_MESSAGE(std::abs(closed - numeric) < 1e-5,
                    "the test's oracle: closed form " << closed << " against the definition integrated " << numeric);
    REQUIRE(std::abs(closed - 0.200044) < 1e-6);
    // One sample per estimate: each is what one sample adds, at most 1 per technique (Eq. 11.26).
    const ps::Scene scene = perpendicular(1, 1, 1);
    const ps::ElementMesh mesh(scene, 1, 1);
    const int n = 32768;
    ps::stats::Welford w;
    double largest = 0.0;
    ps::Rng rng(ps::testseed::seed(1103));
    for (int k = 0; k < n; ++k) {
        const double f = ps::formFactor(scene, mesh, 0, 1, 1, rng);
        largest = std::max(largest, f);
        w.add(f);
    }
    CHECK_MESSAGE(largest <= 2.0 + 1e-6,
                  "formFactor with 1 sample between squares that share an edge: expected at most 2 (each technique "
                  "adds g / (1 + g) <= 1, Eq. 11.26), got "
                      << num(largest)
                      << ": area sampling without the balance heuristic has infinite variance here (Eq. 11.25)");
    const ps::stats::TTestResult t = ps::stats::tTest(w, closed, alpha(), 0.01);
    CHECK_MESSAGE(t.passed,
                  "formFactor between perpendicular unit squares with a common edge: expected the closed form "
                      << num(closed) << ", got " << num(w.mean) << " (ratio " << num(w.mean / closed) << ")\n  "
                      << t.report);
}

TEST_CASE(
    "radiosity: reciprocity A_1 F_12 = A_2 F_21 for perpendicular rectangles of areas 0.5 and 2 (t-tests, Eq. 11.22) [1 pt]") {
    // Common edge l = 1; rectangle 1 is 0.5 wide, rectangle 2 is 2 high.
    const double F12 = perpendicularRectangles(1, 0.5, 2), F21 = perpendicularRectangles(1, 2, 0.5);
    REQUIRE_MESSAGE(std::abs(0.5 * F12 - 2.0 * F21) < 1e-9,
                    "the closed forms themselves: A_1 F_12 = " << 0.5 * F12 << ", A_2 F_21 = " << 2.0 * F21);
    REQUIRE(std::abs(F12 - perpendicularRectanglesNumeric(1, 0.5, 2)) < 1e-5);
    const ps::Scene scene = perpendicular(1, 0.5, 2);
    checkFormFactor("from the 0.5 x 1 rectangle to the 1 x 2 one (they share an edge)", scene, 0, 1, F12, 16384, 4,
                    1104);
    checkFormFactor("from the 1 x 2 rectangle to the 0.5 x 1 one (F_21 = F_12 A_1 / A_2)", scene, 1, 0, F21, 16384, 4,
                    1105);
}

TEST_CASE(
    "radiosity: no form factor through a wall: a square blocking every line between two squares gives F = 0 (Eq. 11.22) [1 pt]") {
    const ps::Scene scene = opposedSquares(1.0, true);
    const ps::ElementMesh mesh(scene, 1, 1);
    ps::Rng rng(ps::testseed::seed(1106));
    for (int dir = 0; dir < 2; ++dir) {
        const float F = ps::formFactor(scene, mesh, dir, 1 - dir, 4096, rng);
        CHECK_MESSAGE(F == 0.0f, "formFactor between two opposed squares with a larger square between them (element "
                                     << dir << " to " << 1 - dir
                                     << "): expected exactly 0 (V(x, y) = 0 for every pair: the shadow ray of the "
                                        "area technique is blocked, and the cosine rays hit the blocker first), got "
                                     << num(F));
    }
    // And not 0 without the blocker (the same squares, so the test above can fail).
    const ps::Scene open = opposedSquares(1.0, false);
    const ps::ElementMesh openMesh(open, 1, 1);
    const float F = ps::formFactor(open, openMesh, 0, 1, 4096, rng);
    CHECK_MESSAGE(F > 0.15f,
                  "formFactor between the same squares without the blocker: expected about 0.2, got " << num(F));
}

TEST_CASE("radiosity: the form factors from an element of a closed box sum to 1 (t-tests, Eq. 11.22) [2 pts]") {
    // A box 1 x 2 x 3 cut into 3 x 3 elements a face: every line from an element's front ends on
    // another element's front, so sum_j F_ij = 1. For a corner element, an edge element and a
    // middle element (of different faces and sizes), n independent sums, each of formFactor with
    // 8 samples to every element j.
    const ps::Scene scene = closedBox(1, 2, 3, 0.5f, 0.0f);
    const ps::ElementMesh mesh(scene, 3, 3);
    const int n = 512;
    for (const int i : {0, mesh.first(2) + 1, mesh.first(5) + 4}) {
        ps::stats::Welford w;
        for (int k = 0; k < n; ++k) {
            double sum = 0.0;
            for (int j = 0; j < mesh.size(); ++j) {
                if (mesh[j].quad == mesh[i].quad) continue;  // 0: the same flat quad
                ps::Rng rng = ps::taskRng(ps::testseed::seed(1107), uint32_t(k), uint32_t(i * mesh.size() + j));
                sum += ps::formFactor(scene, mesh, i, j, 8, rng);
            }
            w.add(sum);
        }
        const ps::stats::TTestResult t = ps::stats::tTest(w, 1.0, alpha(), 0.01);
        CHECK_MESSAGE(t.passed, "sum over j of formFactor(i = " << i << ", j) in a closed box (element of quad "
                                                                << mesh[i].quad << ", area " << num(mesh[i].area)
                                                                << "): expected 1 (Eq. 11.22), got " << num(w.mean)
                                                                << "\n  " << t.report);
    }
}
