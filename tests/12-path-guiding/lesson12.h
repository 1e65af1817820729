// Shared by lesson 12's graded tests: the significance level, hand-made directional trees and
// their oracles (the energy of any dyadic square of the cylindrical map, computed from the nodes
// by the test's own recursion), replayed numbers, small scenes written in the test.
#pragma once
#include "alpha.h"
#include <doctest/doctest.h>
#include <cmath>
#include <functional>
#include <string>
#include <vector>
#include "12-path-guiding/guiding.h"
#include "format.h"
#include "lesson_files.h"
#include "render_helpers.h"
#include "scene_loader.h"
#include "seed.h"
#include "statistics.h"

namespace lesson12 {

using ps::Color;
using ps::Vec2;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;
using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;

// Statistical tests in this suite (every other check is exact: hand-made trees and their
// energies, the spatial tree's boxes, a hand-made path's records, the replayed numbers):
//   chi-square: the directional tree's sampling against its energies; the guided mixture's
//               sampling against its pdf                                                  -> 2
//   z-test:     the learned field's irradiance against the lamp's (test_learning.cpp)      -> 1
//   z-tests:    pt-guided, pt-guided-adrrs and lt-adrrs against the stored references, per
//               pixel and on the whole image's mean                                        -> 6
//   t-test:     the power photons store with roulette and splitting by importance          -> 1
// m = 10; each runs at the Sidak level alpha' = 1 - (1 - a_L)^(1/10) of this lesson's share a_L
// of the whole graded suite's 1 % (tests/support/alpha.h).
constexpr int kStatisticalTests = 10;
inline double alpha() { return ps::testalpha::perTest(kStatisticalTests); }
// The two-sided critical value of the standard normal at alpha() (bisection on its tail).
inline double zCritical() {
    double lo = 0.0, hi = 20.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (ps::stats::normalTwoSided(mid) > alpha() ? lo : hi) = mid;
    }
    return hi;
}

constexpr double kPiD = 3.14159265358979323846;

// A dyadic square of the cylindrical map: [x, x + size) x [y, y + size).
struct Square {
    double x = 0.0, y = 0.0, size = 1.0;
    Square quadrant(int i) const {
        const double h = 0.5 * size;
        return {x + (i & 1) * h, y + (i >> 1) * h, h};
    }
    bool contains(double px, double py) const { return px >= x && px < x + size && py >= y && py < y + size; }
};

// Every leaf quadrant of a tree with its square and energy (the test's own recursion over the nodes).
struct Leaf {
    Square square;
    double energy = 0.0;
    int depth = 0;
};
inline void leavesOf(const ps::DirectionalTree& t, uint32_t node, const Square& sq, int depth, std::vector<Leaf>& out) {
    for (int i = 0; i < 4; ++i) {
        const ps::QuadNode& q = t.nodes[node];
        if (q.child[i] != 0) leavesOf(t, q.child[i], sq.quadrant(i), depth + 1, out);
        else out.push_back({sq.quadrant(i), double(q.energy[i]), depth + 1});
    }
}
inline std::vector<Leaf> leavesOf(const ps::DirectionalTree& t) {
    std::vector<Leaf> out;
    leavesOf(t, 0, Square(), 0, out);
    return out;
}
inline double totalOf(const std::vector<Leaf>& leaves) {
    double e = 0.0;
    for (const Leaf& l : leaves) e += l.energy;
    return e;
}
// The energy of the leaves within square sq, each leaf spread evenly over its own square.
inline double energyIn(const std::vector<Leaf>& leaves, const Square& sq) {
    double e = 0.0;
    for (const Leaf& l : leaves) {
        const double ox =
            std::max(0.0, std::min(sq.x + sq.size, l.square.x + l.square.size) - std::max(sq.x, l.square.x));
        const double oy =
            std::max(0.0, std::min(sq.y + sq.size, l.square.y + l.square.size) - std::max(sq.y, l.square.y));
        e += l.energy * ox * oy / (l.square.size * l.square.size);
    }
    return e;
}

// The direction of the square's point (u, v) (the cylindrical map, lesson 1's Eq. 1.8, written
// out here: z = 1 - 2u, phi = 2 pi v) and back.
inline Vec3 directionOf(double u, double v) {
    const double z = 1.0 - 2.0 * u, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPiD * v;
    return Vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
}
inline void squareOf(const Vec3& w, double& u, double& v) {
    u = (1.0 - double(w.z)) * 0.5;
    double phi = std::atan2(double(w.y), double(w.x));
    if (phi < 0.0) phi += 2.0 * kPiD;
    v = phi / (2.0 * kPiD);
    if (v >= 1.0) v = 0.0;
}

// A hand-made tree of four levels: the root's quadrants 0 and 3 cut; quadrant 0's node cut again
// in its quadrant 2, and that node once more in its quadrant 1 (depth 4); energies chosen so that
// quadrants' sums hold and no two leaves have the same density; quadrant 1 of the root is empty.
inline ps::DirectionalTree handTree() {
    ps::DirectionalTree t;
    t.nodes.resize(5);
    // node 3 (depth 3, under node 1's quadrant 2): quadrant 1 cut into node 4
    t.nodes[4].energy[0] = 0.5f, t.nodes[4].energy[1] = 3.0f, t.nodes[4].energy[2] = 0.25f,
    t.nodes[4].energy[3] = 0.25f;
    t.nodes[3].energy[0] = 0.75f, t.nodes[3].energy[1] = 4.0f, t.nodes[3].energy[2] = 0.125f,
    t.nodes[3].energy[3] = 1.125f;
    t.nodes[3].child[1] = 4;
    t.nodes[1].energy[0] = 2.0f, t.nodes[1].energy[1] = 1.5f, t.nodes[1].energy[2] = 6.0f, t.nodes[1].energy[3] = 0.5f;
    t.nodes[1].child[2] = 3;
    t.nodes[2].energy[0] = 0.25f, t.nodes[2].energy[1] = 1.0f, t.nodes[2].energy[2] = 0.0f,
    t.nodes[2].energy[3] = 2.75f;
    t.nodes[0].energy[0] = 10.0f, t.nodes[0].energy[1] = 0.0f, t.nodes[0].energy[2] = 1.0f, t.nodes[0].energy[3] = 4.0f;
    t.nodes[0].child[0] = 1;
    t.nodes[0].child[3] = 2;
    return t;
}

// The leaf (from leavesOf) whose square contains (u, v).
inline const Leaf* leafAt(const std::vector<Leaf>& leaves, double u, double v) {
    for (const Leaf& l : leaves)
        if (l.square.contains(u, v)) return &l;
    return nullptr;
}

}  // namespace lesson12

namespace lesson12 {

// A point of the unit cube, its coordinates drawn x, y, z in this order (C++ evaluates a
// constructor's arguments in no fixed order).
inline Vec3 uniform3(ps::Rng& rng) {
    const float x = rng.uniform(), y = rng.uniform();
    return Vec3(x, y, rng.uniform());
}

// A closed diffuse box [0, 2] x [0, 1] x [0, 1] seen from inside, with a lamp under its ceiling if
// `lamp`; materials: 0 "w" diffuse albedo (0.5, 0.25, 1), 1 "m" a mirror, 2 "p" Phong 10 albedo 0.6
// (the last two used by no surface: for vertices made by hand).
inline ps::Scene handScene(bool lamp = false) {
    std::string text =
        "camera eye 1 0.5 0.5  target 2 0.5 0.5  up 0 1 0  fov 60  resolution 4 4\n"
        "material w diffuse albedo 0.5 0.25 1\n"
        "material m mirror albedo 1 1 1\n"
        "material p phong albedo 0.6 0.6 0.6 exponent 10\n"
        "quad 0 0 0  2 0 0  2 0 1  0 0 1  material w\n"
        "quad 0 1 0  0 1 1  2 1 1  2 1 0  material w\n"
        "quad 0 0 0  0 0 1  0 1 1  0 1 0  material w\n"
        "quad 2 0 0  2 1 0  2 1 1  2 0 1  material w\n"
        "quad 0 0 0  0 1 0  2 1 0  2 0 0  material w\n"
        "quad 0 0 1  2 0 1  2 1 1  0 1 1  material w\n";
    if (lamp) text += "quad 0.9 0.999 0.4  1.1 0.999 0.4  1.1 0.999 0.6  0.9 0.999 0.6  emission 4 4 4\n";
    return ps::parseScene(text, "hand-box.scene");
}

// A vertex made by hand: a hit at p with normal n and material, seen from wo, throughput beta.
inline ps::WalkVertex handVertex(const Vec3& p, const Vec3& n, int material, const Vec3& wo, const Color& beta) {
    ps::WalkVertex v;
    v.hit = true;
    v.sp.p = p;
    v.sp.n = n;
    v.sp.material = material;
    v.wo = glm::normalize(wo);
    v.beta = beta;
    v.bounces = 2;
    return v;
}

// Lesson 10's window written out (Eq. 10.2, 10.5-10.7; the test's own oracle): q for weight nu,
// pixel estimate I and adjoint Psi (one number).
inline double windowQ(double nu, double I, double psi) {
    const double lower = psi > 0.0 ? 2.0 * (I / psi) / 6.0 : HUGE_VAL, upper = 5.0 * lower;
    double q = 1.0;
    if (nu < lower) q = nu / lower;
    else if (nu > upper) q = nu / upper;
    return std::min(8.0, std::max(0.05, q));
}

}  // namespace lesson12
