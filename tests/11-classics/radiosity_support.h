// Shared by lesson 11's radiosity tests: the significance level, small scenes of quads written in
// the test, and the independent oracles: the closed-form form factors of two directly opposed
// rectangles and of two perpendicular rectangles with a common edge (Howell's catalogue, C-11 and
// C-14), each checked here against a numerical integration of the definition (Eq. 11.22).
#pragma once
#include "lesson11.h"
#include <doctest/doctest.h>
#include <cmath>
#include <functional>
#include <string>
#include <vector>
#include "11-classics/radiosity.h"
#include "format.h"
#include "lesson_files.h"
#include "render_helpers.h"
#include "scene_loader.h"
#include "seed.h"
#include "statistics.h"

namespace lesson11radiosity {

using ps::Color;
using ps::Vec3;
using ps::fmt::num;
using ps::fmt::str;
using ps::testfiles::loadSceneAt;
using ps::testfiles::sourcePath;

// Statistical tests of the radiosity part of lesson 11 (every other check is exact: the point
// form factor, the shooting step, the shooter, the ambient term, the furnace with exact form
// factors, a blocked pair, the bound of each sample; or a fixed-seed bound with its measured
// margin: the furnace and the Cornell box with ray-cast form factors):
//   t-tests of formFactor against closed forms: opposed squares, perpendicular squares with a
//            common edge, and both directions of perpendicular rectangles of different
//            areas (reciprocity)                                                          -> 4
//   t-tests of sum_j F_ij = 1 in a closed box, for three elements                         -> 3
// 7 of lesson 11's m = 16 (lesson11.h), each at lesson11::alpha().
using lesson11::alpha;                       // the lesson's level: all 16 of its statistical tests
using lesson11::kStatisticalTestsRadiosity;  // counted in lesson11.h

// ---------------------------------------------------------------------------------------------
// Closed forms (Howell, "A catalog of radiation heat transfer configuration factors").

// C-11: from a rectangle a x b to the directly opposed, parallel, equal rectangle at distance c.
inline double opposedRectangles(double a, double b, double c) {
    const double X = a / c, Y = b / c, X2 = X * X, Y2 = Y * Y;
    const double s = std::log(std::sqrt((1 + X2) * (1 + Y2) / (1 + X2 + Y2))) +
                     X * std::sqrt(1 + Y2) * std::atan(X / std::sqrt(1 + Y2)) +
                     Y * std::sqrt(1 + X2) * std::atan(Y / std::sqrt(1 + X2)) - X * std::atan(X) - Y * std::atan(Y);
    return 2.0 / (ps::kPi * X * Y) * s;
}

// C-14: from rectangle 1 (width w away from the common edge of length l) to the perpendicular
// rectangle 2 (height h away from the edge).
inline double perpendicularRectangles(double l, double w, double h) {
    const double H = h / l, W = w / l, H2 = H * H, W2 = W * W, D = std::sqrt(H2 + W2);
    const double logTerm = std::log((1 + W2) * (1 + H2) / (1 + W2 + H2)) +
                           W2 * std::log(W2 * (1 + W2 + H2) / ((1 + W2) * (W2 + H2))) +
                           H2 * std::log(H2 * (1 + H2 + W2) / ((1 + H2) * (H2 + W2)));
    return (W * std::atan(1 / W) + H * std::atan(1 / H) - D * std::atan(1 / D) + 0.25 * logTerm) / (ps::kPi * W);
}

// ---------------------------------------------------------------------------------------------
// Numerical integration of the definition, to check the closed forms (not the submission).

// Gauss-Legendre nodes and weights on [0, 1] (n points, Newton on the Legendre polynomial).
inline void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
    x.assign(size_t(n), 0.0);
    w.assign(size_t(n), 0.0);
    for (int i = 0; i < n; ++i) {
        double z = std::cos(ps::kPi * (i + 0.75) / (n + 0.5)), dp = 0.0;
        for (int it = 0; it < 100; ++it) {
            double p0 = 1.0, p1 = 0.0;
            for (int k = 1; k <= n; ++k) {
                const double p2 = p1;
                p1 = p0;
                p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
            }
            dp = n * (z * p0 - p1) / (z * z - 1.0);
            const double dz = p0 / dp;
            z -= dz;
            if (std::abs(dz) < 1e-15) break;
        }
        x[size_t(i)] = 0.5 * (1.0 - z);
        w[size_t(i)] = 1.0 / ((1.0 - z * z) * dp * dp);
    }
}

// F from the rectangle a x b at z = 0 (normal +z) to the opposed one at z = c, by the definition
// (1/A_1) int int cos cos / (pi r^2) dA dA with a Gauss-Legendre product rule (the integrand is
// smooth: the rectangles are apart).
inline double opposedRectanglesNumeric(double a, double b, double c, int n = 12) {
    std::vector<double> x, w;
    gaussLegendre(n, x, w);
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                for (int l = 0; l < n; ++l) {
                    const double dx = a * (x[size_t(i)] - x[size_t(k)]), dy = b * (x[size_t(j)] - x[size_t(l)]);
                    const double r2 = dx * dx + dy * dy + c * c;
                    sum += w[size_t(i)] * w[size_t(j)] * w[size_t(k)] * w[size_t(l)] * c * c / (ps::kPi * r2 * r2);
                }
    return sum * a * b;  // (1 / A_1) * A_1 * A_2 * mean
}

// The form factor from a point p with unit normal n to a polygon (corners in order), by Lambert's
// contour integral: (1 / 2 pi) sum over edges of the angle the edge subtends times n . (unit normal
// of the plane through p and the edge); exact for an unoccluded polygon in front of p.
inline double pointToPolygon(const glm::dvec3& p, const glm::dvec3& n, const std::vector<glm::dvec3>& poly) {
    double s = 0.0;
    for (size_t k = 0; k < poly.size(); ++k) {
        const glm::dvec3 a = glm::normalize(poly[k] - p), b = glm::normalize(poly[(k + 1) % poly.size()] - p);
        const glm::dvec3 c = glm::cross(a, b);
        const double len = glm::length(c);
        if (len < 1e-300) continue;
        s += std::atan2(len, glm::dot(a, b)) * glm::dot(n, c / len);
    }
    return std::abs(s) / (2.0 * ps::kPi);
}

// F from rectangle 1 (x in [0, w], y in [0, l] at z = 0, normal +z) to rectangle 2 (x = 0, y in
// [0, l], z in [0, h], normal +x): the point-to-polygon form factor integrated over rectangle 1,
// in the distance d = t^2 from the common edge (which smooths the logarithmic singularity there).
inline double perpendicularRectanglesNumeric(double l, double w, double h, int n = 48) {
    std::vector<double> x, wt;
    gaussLegendre(n, x, wt);
    const std::vector<glm::dvec3> rect2 = {{0, 0, 0}, {0, l, 0}, {0, l, h}, {0, 0, h}};
    const double tMax = std::sqrt(w);
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double t = tMax * x[size_t(i)], d = t * t;
            const double y = l * x[size_t(j)];
            const double f = pointToPolygon({d, y, 0}, {0, 0, 1}, rect2);
            sum += wt[size_t(i)] * wt[size_t(j)] * f * 2.0 * t * tMax * l;
        }
    return sum / (w * l);
}

// ---------------------------------------------------------------------------------------------
// Scenes.

inline std::string camera() { return "camera eye 0.5 0.5 -3  target 0.5 0.5 0  fov 40  resolution 8 8\n"; }

inline std::string corners(const std::vector<Vec3>& c) {
    std::string s;
    for (const Vec3& p : c) s += num(p.x) + " " + num(p.y) + " " + num(p.z) + "  ";
    return s;
}

// Two directly opposed unit squares, distance c: element 0 at z = 0 facing +z, element 1 at z = c
// facing -z; with `blocker`, a larger square between them (facing -z) blocks every line between
// them.
inline ps::Scene opposedSquares(double c, bool blocker = false) {
    const float z = float(c);
    std::string text = camera() + "material w diffuse albedo 0.5 0.5 0.5\n";
    text += "quad " + corners({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}) + "material w\n";
    text += "quad " + corners({{0, 0, z}, {0, 1, z}, {1, 1, z}, {1, 0, z}}) + "material w\n";
    if (blocker)
        text += "quad " + corners({{-1, -1, z / 2}, {-1, 2, z / 2}, {2, 2, z / 2}, {2, -1, z / 2}}) + "material w\n";
    return ps::parseScene(text, "opposed-squares.scene");
}

// Rectangle 1: x in [0, w], y in [0, l], z = 0, facing +z; rectangle 2: x = 0, y in [0, l],
// z in [0, h], facing +x; they share the edge x = z = 0.
inline ps::Scene perpendicular(double l, double w, double h) {
    const float L = float(l), W = float(w), H = float(h);
    std::string text = camera() + "material w diffuse albedo 0.5 0.5 0.5\n";
    text += "quad " + corners({{0, 0, 0}, {W, 0, 0}, {W, L, 0}, {0, L, 0}}) + "material w\n";
    text += "quad " + corners({{0, 0, 0}, {0, L, 0}, {0, L, H}, {0, 0, H}}) + "material w\n";
    return ps::parseScene(text, "perpendicular.scene");
}

// A closed box [0, sx] x [0, sy] x [0, sz], every face facing inward, of albedo a, emitting Le
// (0: none) from every face; the camera inside.
inline ps::Scene closedBox(float sx, float sy, float sz, float a, float Le) {
    const std::string al = num(a) + " " + num(a) + " " + num(a);
    std::string opt = "material w";
    if (Le > 0.0f) opt += " emission " + num(Le) + " " + num(Le) + " " + num(Le);
    std::string text = "camera eye " + num(sx / 2) + " " + num(sy / 2) + " " + num(sz / 2) + "  target " + num(sx / 2) +
                       " " + num(sy / 2) + " " + num(sz) + "  fov 90  resolution 8 8\n" + "material w diffuse albedo " +
                       al + "\n";
    const float X = sx, Y = sy, Z = sz;
    text += "quad " + corners({{0, 0, 0}, {0, 0, Z}, {X, 0, Z}, {X, 0, 0}}) + opt + "\n";  // floor y = 0
    text += "quad " + corners({{0, Y, 0}, {X, Y, 0}, {X, Y, Z}, {0, Y, Z}}) + opt + "\n";  // ceiling y = Y
    text += "quad " + corners({{0, 0, 0}, {0, Y, 0}, {0, Y, Z}, {0, 0, Z}}) + opt + "\n";  // x = 0
    text += "quad " + corners({{X, 0, 0}, {X, 0, Z}, {X, Y, Z}, {X, Y, 0}}) + opt + "\n";  // x = X
    text += "quad " + corners({{0, 0, 0}, {X, 0, 0}, {X, Y, 0}, {0, Y, 0}}) + opt + "\n";  // z = 0
    text += "quad " + corners({{0, 0, Z}, {0, Y, Z}, {X, Y, Z}, {X, 0, Z}}) + opt + "\n";  // z = Z
    return ps::parseScene(text, "closed-box.scene");
}

// `n` independent estimates of F_ij, each formFactor with `samples` samples from its own
// generator taskRng(seed, i, k).
inline ps::stats::Welford independentEstimates(const ps::Scene& scene, const ps::ElementMesh& mesh, int i, int j, int n,
                                               int samples, uint64_t seed) {
    ps::stats::Welford w;
    for (int k = 0; k < n; ++k) {
        ps::Rng rng = ps::taskRng(seed, uint32_t(i), uint32_t(k));
        w.add(ps::formFactor(scene, mesh, i, j, samples, rng));
    }
    return w;
}

}  // namespace lesson11radiosity
