// Lesson 12, graded: roulette and splitting from an adjoint (Eq. 12.14-12.17 with lesson 10's
// window): the window's q against lesson 10's formulas written out in the test, the field's
// adjoint and a camera path's decision on a hand-made field of two cells, the importons of a
// camera path, and a particle's decision on a hand-filled importance cache.
#include "lesson12.h"

using namespace lesson12;

namespace {
double mean(const Color& c) { return (double(c.r) + c.g + c.b) / 3.0; }
}  // namespace

TEST_CASE(
    "window: q from a throughput, an adjoint and the measurement an ideal path brings (Eq. 12.15, 10.5-10.7) [1 pt]") {
    struct Case {
        Color beta, adjoint;
        float I;
        const char* what;
    };
    for (const Case& c :
         {Case{Color(0.02f), Color(1.0f), 1.0f, "far below the window: roulette"},
          Case{Color(0.5f), Color(1.0f), 1.0f, "inside the window"},
          Case{Color(4.0f), Color(1.0f), 1.0f, "above: splitting"},
          Case{Color(4.0f, 0.1f, 0.1f), Color(2.0f, 0.2f, 0.2f), 3.0f, "a coloured adjoint weights the red channel"},
          Case{Color(4.0f, 0.1f, 0.1f), Color(0.2f, 2.0f, 2.0f), 3.0f, "... or the others"},
          Case{Color(0.3f, 0.6f, 0.9f), Color(0.0f), 1.0f, "a black adjoint: q_min"},
          Case{Color(0.3f), Color(1.0f), 0.0f, "I = 0 under a path that expects light: q_max"},
          Case{Color(1e4f), Color(1.0f), 1.0f, "far above: q_max"}}) {
        const double sum = double(c.adjoint.r) + c.adjoint.g + c.adjoint.b;
        const double nu =
            sum > 0.0
                ? (double(c.beta.r) * c.adjoint.r + double(c.beta.g) * c.adjoint.g + double(c.beta.b) * c.adjoint.b) /
                      sum
                : mean(c.beta);
        const double want = windowQ(nu, c.I, sum / 3.0);
        const double got = ps::windowContinuations(c.beta, c.adjoint, c.I);
        CHECK_MESSAGE(std::abs(got - want) <= 1e-5 * want,
                      "windowContinuations(beta " << str(c.beta) << ", adjoint " << str(c.adjoint) << ", measurement "
                                                  << c.I << ") (" << c.what << "): expected q = " << num(want)
                                                  << " (nu = " << num(nu) << "), got " << num(got));
    }
}

TEST_CASE("ADRRS on the field: the adjoint of a cell and a camera path's decision (Eq. 12.14, 12.15, 10.9) [2 pts]") {
    const ps::Scene scene = handScene();
    // Two cells: the box [0, 2] x [0, 1] x [0, 1] cut in x at 1; cell 1 (x < 1) reliable on every
    // side but +x, cell 0 not at all.
    ps::AABB box;
    box.lo = Vec3(0.0f);
    box.hi = Vec3(2.0f, 1.0f, 1.0f);
    ps::SpatialTree tree(box);
    tree.nodes.resize(3);
    tree.nodes[0].child[0] = 1, tree.nodes[0].child[1] = 2;
    tree.nodes[1].axis = tree.nodes[2].axis = 1;
    tree.nodes[1].cell = 1, tree.nodes[2].cell = 0;
    std::vector<ps::GuideCell> cells(2);
    const float E[6] = {1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f};  // +x, -x, +y, -y, +z, -z
    for (int s = 0; s < 6; ++s) {
        cells[1].side[s].irradiance = E[s], cells[0].side[s].irradiance = 100.0f * E[s];
        cells[1].side[s].reliable = s != 0;
    }
    const ps::GuideField field(tree, cells);
    const Color albedo(0.5f, 0.25f, 1.0f);  // material 0

    struct AdjCase {
        Vec3 n, wo;
        int side;
        const char* what;
    };
    for (const AdjCase& c : {AdjCase{Vec3(0, 1, 0), Vec3(0.1f, 1, 0), 2, "the floor seen from above: +y"},
                             AdjCase{Vec3(0, 1, 0), Vec3(0.1f, -1, 0.2f), 3, "its back: -y"},
                             AdjCase{Vec3(-1, 0, 0), Vec3(-1, 0.3f, 0), 1, "a wall facing -x"},
                             AdjCase{Vec3(0, 0, 1), Vec3(0.2f, 0, -1), 5, "+z seen from -z: the normal turned"}}) {
        const Color got = ps::fieldAdjoint(field.cell(1), scene.materials[0], c.n, glm::normalize(c.wo));
        const Color want = albedo * (E[c.side] / 3.14159265f);
        CHECK_MESSAGE(glm::length(got - want) <= 1e-5f * glm::length(want),
                      "fieldAdjoint (" << c.what << ", irradiance " << E[c.side] << " on that side, albedo "
                                       << str(albedo) << "): expected albedo / pi times it, " << str(want) << ", got "
                                       << str(got));
    }

    // The pixel estimate at a first vertex on the floor of cell 1, seen from above.
    const Vec3 up(0, 1, 0);
    const ps::WalkVertex x0 = handVertex(Vec3(0.5f, 0.0f, 0.5f), up, 0, Vec3(0.3f, 1.0f, 0.1f), Color(1.0f));
    const double I = mean(albedo) * E[2] / 3.14159265;
    const float gotI = ps::fieldPixelEstimate(field, scene, x0);
    CHECK_MESSAGE(std::abs(gotI - I) <= 1e-5 * I,
                  "fieldPixelEstimate at a floor point of a reliable cell: expected the "
                  "mean of its adjoint, "
                      << num(I) << ", got " << num(gotI));
    ps::WalkVertex miss;
    ps::WalkVertex unreliable = handVertex(Vec3(1.5f, 0.0f, 0.5f), up, 0, Vec3(0, 1, 0), Color(1.0f));
    ps::WalkVertex mirror = x0;
    mirror.sp.material = 1;
    ps::WalkVertex plusX = handVertex(Vec3(0.0f, 0.5f, 0.5f), Vec3(1, 0, 0), 0, Vec3(1, 0.2f, 0), Color(1.0f));
    for (const std::pair<const ps::WalkVertex*, const char*> c :
         {std::make_pair(&miss, "a miss"), std::make_pair(&unreliable, "a cell that is not reliable"),
          std::make_pair(&mirror, "a mirror"), std::make_pair(&plusX, "a side (+x) that is not reliable")}) {
        const float got = ps::fieldPixelEstimate(field, scene, *c.first);
        CHECK_MESSAGE(got == -1.0f, "fieldPixelEstimate at " << c.second << ": expected -1, got " << num(got));
    }

    // Decisions at vertices of cell 1 (the previous vertex in cell 0, which says something else).
    for (const Color& beta : {Color(0.01f), Color(0.3f), Color(5.0f), Color(2.0f, 0.1f, 0.5f)}) {
        ps::WalkVertex v = handVertex(Vec3(0.25f, 1.0f, 0.5f), Vec3(0, -1, 0), 0, Vec3(0.2f, -1.0f, 0.0f), beta);
        v.pPrev = Vec3(1.8f, 0.0f, 0.5f);
        const Color adj = albedo * (E[3] / 3.14159265f);  // the ceiling seen from below: -y
        const double sum = double(adj.r) + adj.g + adj.b;
        const double nu = (double(beta.r) * adj.r + double(beta.g) * adj.g + double(beta.b) * adj.b) / sum;
        const double want = windowQ(nu, I, sum / 3.0);
        const ps::Decision d = ps::fieldDecision(field, scene, v, float(I));
        CHECK_MESSAGE((d.decided && std::abs(d.q - want) <= 1e-5 * want),
                      "fieldDecision at a ceiling point of a reliable cell, beta "
                          << str(beta) << ", I~ " << num(I) << ": expected q = " << num(want)
                          << " (the cell where the path is, the side it sees), got "
                          << (d.decided ? "q = " + num(d.q) : std::string("no decision")));
    }
    struct NoCase {
        ps::WalkVertex v;
        float I;
        const char* what;
    };
    ps::WalkVertex v1 = handVertex(Vec3(0.25f, 1.0f, 0.5f), Vec3(0, -1, 0), 0, Vec3(0, -1, 0), Color(0.5f));
    ps::WalkVertex v2 = v1;
    v2.sp.material = 1;
    ps::WalkVertex v3 = handVertex(Vec3(1.75f, 1.0f, 0.5f), Vec3(0, -1, 0), 0, Vec3(0, -1, 0), Color(0.5f));
    v3.pPrev = Vec3(0.2f, 0.0f, 0.5f);
    ps::WalkVertex v4 = handVertex(Vec3(0.0f, 0.5f, 0.5f), Vec3(1, 0, 0), 0, Vec3(1, 0.2f, 0), Color(0.5f));
    for (const NoCase& c :
         {NoCase{v1, -1.0f, "no pixel estimate (I~ = -1)"}, NoCase{v2, float(I), "a mirror"},
          NoCase{v3, float(I), "a cell that is not reliable (the previous vertex's is)"},
          NoCase{v4, float(I), "a side (+x) that is not reliable"}, NoCase{miss, float(I), "a miss"}}) {
        const ps::Decision d = ps::fieldDecision(field, scene, c.v, c.I);
        CHECK_MESSAGE(!d.decided, "fieldDecision at " << c.what
                                                      << ": expected no decision (the walk's own roulette), "
                                                         "got q = "
                                                      << num(d.q));
    }
}

TEST_CASE(
    "particles: the importons of a camera path and a particle's decision on their importance (Eq. 12.16, 12.17) [2 pts]") {
    std::vector<ps::ImportanceVertex> path(4);
    path[0] = {true, Vec3(0.1f, 0.2f, 0.3f), Vec3(0, 1, 0), glm::normalize(Vec3(0.2f, 1.0f, 0.0f)), Color(1.0f)};
    path[1] = {false, Vec3(0.5f), Vec3(1, 0, 0), Vec3(1, 0, 0), Color(0.9f)};  // a mirror
    path[2] = {true, Vec3(0.7f, 0.1f, 0.9f), Vec3(0, 0, 1), glm::normalize(Vec3(-0.5f, 0.3f, 1.0f)),
               Color(0.4f, 0.2f, 0.1f)};
    path[3] = {true, Vec3(1.9f, 0.5f, 0.5f), Vec3(-1, 0, 0), glm::normalize(Vec3(-1.0f, 0.0f, 0.2f)),
               Color(0.05f, 0.1f, 0.0f)};
    std::vector<ps::Photon> out(1);
    ps::appendImportons(path, 256, 1024, out);
    REQUIRE_MESSAGE(out.size() == 4,
                    "appendImportons of a camera path with 3 stored vertices of 4, appended to a list of "
                    "1: expected 4 photons, got "
                        << out.size());
    const size_t stored[3] = {0, 2, 3};
    for (size_t k = 0; k < 3; ++k) {
        const ps::Photon& ph = out[1 + k];
        const ps::ImportanceVertex& v = path[stored[k]];
        const Color want = v.beta * (256.0f / 1024.0f);
        CHECK_MESSAGE((glm::length(ph.p - v.p) == 0.0f && glm::length(ph.power - want) <= 1e-6f &&
                       glm::length(ph.wLight() - v.wo) < 1e-3f),
                      "appendImportons: importon " << k << " expected at " << str(v.p) << " with power " << str(want)
                                                   << " (beta times 256 pixels / 1024 paths, Eq. 12.16) and direction "
                                                   << str(v.wo) << ", got " << str(ph.p) << ", " << str(ph.power)
                                                   << ", " << str(ph.wLight()));
    }

    const ps::Scene scene = handScene();
    ps::AABB box;
    box.lo = Vec3(0.0f);
    box.hi = Vec3(2.0f, 1.0f, 1.0f);
    ps::AdjointCache cache(box, 2);
    // The floor's cells (y < 0.5) seen from above: importance 0.2 (x < 1) and 3 (x > 1); from below
    // (side -y) nothing reliable.
    const int lowFloor = cache.entry(Vec3(0.5f, 0.0f, 0.25f), Vec3(0, 1, 0), Vec3(0, 1, 0));
    const int highFloor = cache.entry(Vec3(1.5f, 0.0f, 0.25f), Vec3(0, 1, 0), Vec3(0, 1, 0));
    cache.set(lowFloor, Color(0.2f, 0.1f, 0.3f));
    cache.set(highFloor, Color(3.0f));
    const Color albedo(0.5f, 0.25f, 1.0f);
    const float T = 40.0f;
    for (const auto& c : {std::make_pair(Vec3(0.5f, 0.0f, 0.25f), Color(0.2f, 0.1f, 0.3f)),
                          std::make_pair(Vec3(1.5f, 0.0f, 0.25f), Color(3.0f))})
        for (const Color& beta : {Color(1.0f), Color(30.0f), Color(500.0f, 10.0f, 1.0f)}) {
            ps::WalkVertex y = handVertex(c.first, Vec3(0, 1, 0), 0, Vec3(0.3f, 1.0f, -0.2f), beta);
            y.pPrev = Vec3(1.0f, 1.0f, 0.9f);
            const Color W = albedo * c.second;
            const double sum = double(W.r) + W.g + W.b;
            const double nu = (double(beta.r) * W.r + double(beta.g) * W.g + double(beta.b) * W.b) / sum;
            const double want = windowQ(nu, T, sum / 3.0);
            const ps::Decision d = ps::particleDecision(cache, scene, y, T);
            CHECK_MESSAGE((d.decided && std::abs(d.q - want) <= 1e-5 * want),
                          "particleDecision at " << str(c.first) << " (importance " << str(c.second) << ", albedo "
                                                 << str(albedo) << "), power " << str(beta) << ", image total " << T
                                                 << ": expected q = " << num(want) << ", got "
                                                 << (d.decided ? "q = " + num(d.q) : std::string("no decision")));
        }
    ps::WalkVertex below = handVertex(Vec3(0.5f, 0.0f, 0.25f), Vec3(0, 1, 0), 0, Vec3(0.0f, -1.0f, 0.1f), Color(1.0f));
    ps::WalkVertex mirror = handVertex(Vec3(0.5f, 0.0f, 0.25f), Vec3(0, 1, 0), 1, Vec3(0, 1, 0), Color(1.0f));
    ps::WalkVertex empty = handVertex(Vec3(0.5f, 1.0f, 0.75f), Vec3(0, -1, 0), 0, Vec3(0, -1, 0), Color(1.0f));
    ps::WalkVertex miss;
    for (const std::pair<const ps::WalkVertex*, const char*> c :
         {std::make_pair(&below, "the floor's underside (its entry is empty)"), std::make_pair(&mirror, "a mirror"),
          std::make_pair(&empty, "an entry without importons"), std::make_pair(&miss, "a miss")}) {
        const ps::Decision d = ps::particleDecision(cache, scene, *c.first, T);
        CHECK_MESSAGE(!d.decided, "particleDecision at " << c.second
                                                         << ": expected no decision (the light walk's own roulette), "
                                                            "got q = "
                                                         << num(d.q));
    }
}
