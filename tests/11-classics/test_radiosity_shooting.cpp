// Lesson 11, graded: progressive refinement (Eq. 11.27-11.29): the start, the choice of the
// shooter, one shooting step by hand, the iteration with exact form factors in a furnace box
// (B = E / (1 - rho) to the residual), and the ambient term. Every check is exact (float
// rounding aside): the form factors are given, not estimated.
#include "radiosity_support.h"

using namespace lesson11radiosity;

namespace {

// Three quads of areas 1, 2 and 4 (elements 0, 1, 2 with one element a quad), albedos 0.5,
// (0.2, 0.4, 0.8) and 0.9; the first emits Le = (1, 2, 3), so E_0 = pi (1, 2, 3).
ps::Scene threeQuads() {
    const std::string text = camera() +
                             "material a diffuse albedo 0.5 0.5 0.5\n"
                             "material b diffuse albedo 0.2 0.4 0.8\n"
                             "material c diffuse albedo 0.9 0.9 0.9\n"
                             "quad 0 0 0  1 0 0  1 1 0  0 1 0  material a emission 1 2 3\n"
                             "quad 0 0 3  0 2 3  1 2 3  1 0 3  material b\n"
                             "quad 0 0 0  0 2 0  0 2 2  0 0 2  material c\n";
    return ps::parseScene(text, "three-quads.scene");
}

std::string colour(const Color& c) { return str(Vec3(c.r, c.g, c.b)); }

bool near(const Color& a, const Color& b, float rel = 1e-5f) {
    for (int k = 0; k < 3; ++k)
        if (std::abs(a[k] - b[k]) > rel * std::max(std::abs(b[k]), 1e-3f)) return false;
    return true;
}

}  // namespace

TEST_CASE("radiosity: the solution starts with B = E and unshot = E (Eq. 11.27) [1 pt]") {
    const ps::Scene scene = threeQuads();
    const ps::ElementMesh mesh(scene, 2, 1);
    REQUIRE(mesh.size() == 6);
    const ps::RadiositySolution s = ps::startRadiosity(mesh);
    REQUIRE_MESSAGE(s.B.size() == 6, "startRadiosity: expected B for each of the 6 elements, got " << s.B.size());
    REQUIRE_MESSAGE(s.unshot.size() == 6,
                    "startRadiosity: expected unshot for each of the 6 elements, got " << s.unshot.size());
    CHECK_MESSAGE(s.shots == 0, "startRadiosity: expected 0 shots, got " << s.shots);
    for (int i = 0; i < 6; ++i) {
        const Color E = i < 2 ? ps::kPi * Color(1, 2, 3) : Color(0.0f);
        CHECK_MESSAGE(near(s.B[size_t(i)], E), "startRadiosity: element " << i << ": expected B = E = " << colour(E)
                                                                          << " (the emitted radiosity pi Le), got "
                                                                          << colour(s.B[size_t(i)]));
        CHECK_MESSAGE(near(s.unshot[size_t(i)], E), "startRadiosity: element "
                                                        << i << ": expected unshot = E = " << colour(E)
                                                        << " (the emission is the first power to shoot), got "
                                                        << colour(s.unshot[size_t(i)]));
    }
}

TEST_CASE(
    "radiosity: the shooter is the element with the most unshot power, unshot A, not the most radiosity (Eq. 11.28) [1 pt]") {
    const ps::Scene scene = threeQuads();
    const ps::ElementMesh mesh(scene, 1, 1);
    REQUIRE(mesh.size() == 3);
    REQUIRE(std::abs(mesh[2].area - 4.0f) < 1e-5f);
    ps::RadiositySolution s;
    s.B.assign(3, Color(1.0f));
    // Unshot radiosity (summed over channels) 6, 3, 2.5; power 6, 6, 10.
    s.unshot = {Color(2, 2, 2), Color(1, 1, 1), Color(1, 1, 0.5f)};
    int i = ps::chooseShooter(mesh, s);
    CHECK_MESSAGE(i == 2,
                  "chooseShooter: unshot (2,2,2), (1,1,1), (1,1,0.5) on areas 1, 2, 4: expected element 2 "
                  "(power 10 against 6 and 6), got "
                      << i << (i == 0 ? " (the most unshot radiosity, not power: multiply by the area)" : ""));
    s.unshot[2] = Color(0.0f);
    i = ps::chooseShooter(mesh, s);
    CHECK_MESSAGE(i == 0, "chooseShooter: powers 6, 6, 0: expected the first of the equal ones, 0, got " << i);
    s.unshot = {Color(3, 0, 0), Color(0, 0.9f, 0.9f), Color(0.0f)};
    i = ps::chooseShooter(mesh, s);
    CHECK_MESSAGE(i == 1,
                  "chooseShooter: unshot (3,0,0) on area 1 and (0,0.9,0.9) on area 2: expected element 1 "
                  "(power summed over the channels: 3.6 against 3), got "
                      << i);
    s.unshot.assign(3, Color(0.0f));
    i = ps::chooseShooter(mesh, s);
    CHECK_MESSAGE(i == -1, "chooseShooter: no unshot power anywhere: expected -1, got " << i);
}

TEST_CASE(
    "radiosity: shooting steps by hand: dB_j = rho_j dB_i F_ij A_i / A_j, and unshot_i reset (Eq. 11.28) [2 pts]") {
    const ps::Scene scene = threeQuads();
    const ps::ElementMesh mesh(scene, 1, 1);
    REQUIRE(mesh.size() == 3);
    ps::RadiositySolution s;
    s.B = {Color(5.0f), Color(1.0f), Color(0.0f)};
    s.unshot = {Color(1, 2, 3), Color(0.5f), Color(0.0f)};
    // From element 1 (area 2): to element 0 (area 1, rho 0.5) with F = 0.3, to element 2 (area 4,
    // rho 0.9) with F = 0.25.
    ps::shoot(mesh, s, 1, {0.3f, 0.0f, 0.25f});
    const Color to0(0.5f * 0.5f * 0.3f * 2.0f), to2(0.9f * 0.5f * 0.25f * 2.0f / 4.0f);
    const char* hint =
        " (check: A_i / A_j, not A_j / A_i; rho_j once; dB = unshot_i before the step; add to both B_j and unshot_j)";
    CHECK_MESSAGE(near(s.B[0], Color(5.0f) + to0), "shoot from element 1: B_0 expected " << colour(Color(5.0f) + to0)
                                                                                         << ", got " << colour(s.B[0])
                                                                                         << hint);
    CHECK_MESSAGE(near(s.unshot[0], Color(1, 2, 3) + to0), "shoot from element 1: unshot_0 expected "
                                                               << colour(Color(1, 2, 3) + to0) << ", got "
                                                               << colour(s.unshot[0]) << hint);
    CHECK_MESSAGE(near(s.B[2], to2),
                  "shoot from element 1: B_2 expected " << colour(to2) << ", got " << colour(s.B[2]) << hint);
    CHECK_MESSAGE(near(s.unshot[2], to2),
                  "shoot from element 1: unshot_2 expected " << colour(to2) << ", got " << colour(s.unshot[2]) << hint);
    CHECK_MESSAGE(near(s.B[1], Color(1.0f)),
                  "shoot from element 1: its own B must not change, expected (1, 1, 1), got " << colour(s.B[1]));
    CHECK_MESSAGE(s.unshot[1] == Color(0.0f),
                  "shoot from element 1: its unshot must be reset to 0 (it has shot it), got " << colour(s.unshot[1]));
    CHECK_MESSAGE(s.shots == 1, "shoot: expected shots = 1 after one step, got " << s.shots);

    // Then from element 0 (area 1), coloured: to element 1 (rho (0.2, 0.4, 0.8)) with F = 0.1.
    const Color dB = Color(1, 2, 3) + to0;
    ps::shoot(mesh, s, 0, {0.0f, 0.1f, 0.2f});
    const Color to1 = Color(0.2f, 0.4f, 0.8f) * dB * (0.1f * 1.0f / 2.0f);
    const Color to2b = to2 + 0.9f * dB * (0.2f * 1.0f / 4.0f);
    CHECK_MESSAGE(near(s.B[1], Color(1.0f) + to1), "second shot, from element 0: B_1 expected "
                                                       << colour(Color(1.0f) + to1) << ", got " << colour(s.B[1])
                                                       << hint << "; rho is a colour, per channel");
    CHECK_MESSAGE(near(s.unshot[1], to1), "second shot, from element 0: unshot_1 expected "
                                              << colour(to1) << ", got " << colour(s.unshot[1]) << hint);
    CHECK_MESSAGE(near(s.B[2], to2b),
                  "second shot, from element 0: B_2 expected " << colour(to2b) << ", got " << colour(s.B[2]) << hint);
    CHECK_MESSAGE(s.unshot[0] == Color(0.0f), "second shot: unshot_0 must be reset, got " << colour(s.unshot[0]));
    CHECK_MESSAGE(s.shots == 2, "shoot: expected shots = 2 after two steps, got " << s.shots);

    // An element that receives part of its own shot (F_ii > 0, as a curved patch would): what it
    // receives is new unshot power, so unshot_i is reset BEFORE the loop.
    s.unshot = {Color(0.0f), Color(0.0f), Color(1.0f)};
    s.B[2] = Color(1.0f);
    ps::shoot(mesh, s, 2, {0.0f, 0.0f, 0.5f});
    const Color self(0.9f * 0.5f);
    CHECK_MESSAGE(near(s.unshot[2], self), "shoot from element 2 with F_22 = 0.5: unshot_2 expected rho F_22 dB = "
                                               << colour(self) << " (reset before distributing), got "
                                               << colour(s.unshot[2]));
}

TEST_CASE(
    "radiosity: shooting with exact form factors solves a furnace box: B = E / (1 - rho) to the residual (Eq. 11.21, 11.28) [2 pts]") {
    // A closed box 1 x 2 x 3 of albedo 0.5 emitting Le = 1 from every face, 2 x 2 elements a face
    // (areas 0.5 to 1.5), and the form factors of a "well mixed" enclosure, F_ij = A_j / sum A
    // (rows sum to 1, reciprocity holds): the solution of B = E + rho F B is B = E / (1 - rho) =
    // 2 pi everywhere.
    const ps::Scene scene = closedBox(1, 2, 3, 0.5f, 1.0f);
    const ps::ElementMesh mesh(scene, 2, 2);
    double total = 0.0;
    for (const ps::Element& e : mesh.elements()) total += e.area;
    std::vector<float> row;
    for (const ps::Element& e : mesh.elements()) row.push_back(float(e.area / total));
    ps::RadiositySolution s = ps::startRadiosity(mesh);
    REQUIRE(s.B.size() == size_t(mesh.size()));
    int steps = 0;
    for (; steps < 20000; ++steps) {
        if (ps::unshotFraction(mesh, s) < 1e-9) break;
        const int i = ps::chooseShooter(mesh, s);
        if (i < 0) break;
        ps::shoot(mesh, s, i, row);
    }
    CHECK_MESSAGE(steps < 20000,
                  "the shooting loop did not bring the unshot power below 1e-9 of the emitted in 20000 "
                  "steps (unshot "
                      << ps::unshotFraction(mesh, s) << "): is unshot_i reset after a shot?");
    const double expected = ps::kPi / (1.0 - 0.5);
    for (int i = 0; i < mesh.size(); ++i)
        CHECK_MESSAGE(std::abs(s.B[size_t(i)].g - expected) <= 1e-4 * expected,
                      "furnace box with exact form factors: element "
                          << i << " (area " << num(mesh[i].area) << "): expected B = E / (1 - rho) = " << num(expected)
                          << ", got " << colour(s.B[size_t(i)])
                          << " (E / (1 - rho^2) = 4.19 would be rho applied twice; other values the wrong area ratio)");
}

TEST_CASE("radiosity: the ambient term, by hand and exact in a furnace box before the first shot (Eq. 11.29) [1 pt]") {
    const ps::Scene scene = threeQuads();
    const ps::ElementMesh mesh(scene, 1, 1);
    ps::RadiositySolution s;
    s.B.assign(3, Color(0.0f));
    s.unshot = {Color(1, 2, 3), Color(0.5f), Color(0.0f)};
    // rho_avg = (0.5 + 2 (0.2, 0.4, 0.8) + 4 0.9) / 7; sum unshot A / sum A = (2, 3, 4) / 7.
    const Color expected(0.8f, 3.0f / 2.1f, 4.0f / 1.3f);
    const Color got = ps::ambientRadiosity(mesh, s);
    CHECK_MESSAGE(near(got, expected),
                  "ambientRadiosity: areas 1, 2, 4, albedos 0.5, (0.2, 0.4, 0.8), 0.9, unshot (1, 2, 3), "
                  "(0.5, 0.5, 0.5), 0: expected R sum unshot A / sum A with R = 1 / (1 - rho_avg) = "
                      << colour(expected) << ", got " << colour(got));
    // The furnace box before any shot: B + rho ambient = E + rho E / (1 - rho) = E / (1 - rho).
    const ps::Scene box = closedBox(1, 2, 3, 0.5f, 1.0f);
    const ps::ElementMesh boxMesh(box, 2, 2);
    const ps::RadiositySolution start = ps::startRadiosity(boxMesh);
    const Color amb = ps::ambientRadiosity(boxMesh, start);
    const Color shown = start.B.empty() ? Color(0.0f) : start.B[0] + boxMesh[0].rho * amb;
    CHECK_MESSAGE(
        near(shown, Color(2.0f * ps::kPi)),
        "a furnace box (albedo 0.5, E = pi) before the first shot: expected B + rho ambient = E / (1 - rho) = "
        "2 pi exactly, got "
            << colour(shown) << " (ambient " << colour(amb) << ")");
    // Albedo 1 everywhere: R = 1 / (1 - rho_avg) has no finite value; the ambient term must not
    // become infinite or NaN (what it shows there is the implementation's choice).
    const ps::Scene white = closedBox(1, 2, 3, 1.0f, 1.0f);
    const ps::ElementMesh whiteMesh(white, 1, 1);
    const Color ambWhite = ps::ambientRadiosity(whiteMesh, ps::startRadiosity(whiteMesh));
    CHECK_MESSAGE((std::isfinite(ambWhite.r) && std::isfinite(ambWhite.g) && std::isfinite(ambWhite.b)),
                  "a box of albedo 1 (rho_avg = 1): expected a finite ambient term, got " << colour(ambWhite));
}
