// Lesson 0, graded: watertightness. Rays aimed exactly at the shared edges and vertices of
// triangle fans and mesh grids must hit at least one of the triangles that share them: a ray
// that crosses a closed sheet of triangles never falls through a crack between two of them.
// Rays along the coordinate axes pass exactly through dyadic edge points (every coordinate is
// exact in float), the hardest case for an edge test with strict inequalities; the other
// directions (diagonals, directions with a zero component, random ones, every sign) pass within
// float rounding of the edge, where a test that is not watertight lets some rays slip through.
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>
#include "lesson00.h"
#include "seed.h"

using namespace lesson00;

namespace {

using Mesh = std::vector<Triangle>;

// A point a ray is aimed at, and what it is (for the failure message).
struct Target {
    Vec3 p;
    std::string what;
};

int countHits(const Mesh& mesh, const Ray& ray) {
    const ps::WatertightRay wr(ray);
    int hits = 0;
    for (const Triangle& tri : mesh) {
        float t, b1, b2;
        if (ps::intersectTriangle(ray, wr, tri, t, b1, b2)) ++hits;
    }
    return hits;
}

// The triangles of the mesh that contain p (on an edge or at a corner: the ones sharing it),
// for the failure message.
std::string trianglesAt(const Mesh& mesh, const Vec3& p) {
    std::string out;
    for (const Triangle& tri : mesh) {
        const DVec3 p0(tri.p0), e1 = DVec3(tri.p1) - p0, e2 = DVec3(tri.p2) - p0, n = glm::cross(e1, e2);
        const DVec3 x = DVec3(p) - p0;
        const double nn = glm::dot(n, n), size = std::max(glm::length(e1), glm::length(e2));
        const double b1 = glm::dot(glm::cross(x, e2), n) / nn, b2 = glm::dot(glm::cross(e1, x), n) / nn;
        const double dist = std::abs(glm::dot(x, n)) / std::sqrt(nn);
        if (dist < 1e-5 * size && b1 > -1e-5 && b2 > -1e-5 && b1 + b2 < 1.0 + 1e-5) out += "\n  " + str(tri);
    }
    return out;
}

// Directions: the six axes, the eight diagonals, the twelve directions with one zero component,
// and `random` random ones: every sign pattern of the components.
std::vector<Vec3> testDirections(int random, ps::Rng& rng) {
    std::vector<Vec3> dirs;
    for (int axis = 0; axis < 3; ++axis)
        for (float s : {1.0f, -1.0f}) {
            Vec3 d(0.0f);
            d[axis] = s;
            dirs.push_back(d);
        }
    for (float x : {1.0f, -1.0f})
        for (float y : {1.0f, -1.0f}) {
            for (float z : {1.0f, -1.0f}) dirs.push_back(glm::normalize(Vec3(x, y, z)));
            dirs.push_back(glm::normalize(Vec3(x, y, 0.0f)));
            dirs.push_back(glm::normalize(Vec3(x, 0.0f, y)));
            dirs.push_back(glm::normalize(Vec3(0.0f, x, y)));
        }
    for (int i = 0; i < random; ++i) dirs.push_back(randomUnit(rng));
    return dirs;
}

// Fires a ray from target - L d along d at every target, for every direction not within
// ~3 degrees of the surface's plane (normal n); counts the rays that hit no triangle.
void checkNoRayFallsThrough(const Mesh& mesh, const Vec3& n, const std::vector<Target>& targets,
                            const std::vector<Vec3>& dirs, float L, const std::string& meshName) {
    int misses = 0, rays = 0;
    for (const Target& tg : targets)
        for (const Vec3& d : dirs) {
            if (std::abs(glm::dot(d, n)) < 0.05f) continue;
            const Ray ray(tg.p - L * d, d);
            ++rays;
            if (countHits(mesh, ray) == 0 && ++misses <= 5)
                FAIL_CHECK(meshName << ": a ray aimed at " << tg.what << " " << str(tg.p)
                                    << " hit none of the triangles sharing it (expected >= 1 hit)\n  " << str(ray)
                                    << "\n  the triangles sharing it:" << trianglesAt(mesh, tg.p));
        }
    CHECK_MESSAGE(misses == 0, meshName << ": expected 0 of " << rays << " rays through shared edges and vertices to "
                                        << "fall through, got " << misses);
    CHECK(rays > 100);
}

// The tilted plane z = z0 + x/2 - y/4: dyadic (x, y) give dyadic, exactly representable points.
Vec3 onTiltedPlane(float x, float y, float z0) { return Vec3(x, y, z0 + 0.5f * x - 0.25f * y); }

}  // namespace

TEST_CASE(
    "rays: watertight: rays through the shared edges and the centre of a triangle fan never fall through [2 pts]") {
    ps::Rng rng(ps::testseed::seed(9));
    const std::vector<Vec3> dirs = testDirections(100, rng);

    // 1. A planar fan of 16 triangles around c in a tilted plane, rim on a square, all dyadic;
    //    every third triangle wound the other way.
    {
        const float cx = 0.5f, cy = -0.25f, z0 = 1.0f;
        std::vector<Vec3> rim;
        for (int j = 0; j < 4; ++j) rim.push_back(onTiltedPlane(cx + 1.0f, cy - 1.0f + 0.5f * j, z0));
        for (int j = 0; j < 4; ++j) rim.push_back(onTiltedPlane(cx + 1.0f - 0.5f * j, cy + 1.0f, z0));
        for (int j = 0; j < 4; ++j) rim.push_back(onTiltedPlane(cx - 1.0f, cy + 1.0f - 0.5f * j, z0));
        for (int j = 0; j < 4; ++j) rim.push_back(onTiltedPlane(cx - 1.0f + 0.5f * j, cy - 1.0f, z0));
        const Vec3 c = onTiltedPlane(cx, cy, z0);
        Mesh fan;
        for (size_t k = 0; k < rim.size(); ++k) {
            Triangle t{c, rim[k], rim[(k + 1) % rim.size()]};
            if (k % 3 == 2) std::swap(t.p1, t.p2);
            fan.push_back(t);
        }
        std::vector<Target> targets = {{c, "the fan's centre vertex"}};
        for (size_t k = 0; k < rim.size(); ++k)
            for (float s : {0.125f, 0.25f, 0.5f, 0.75f, 0.875f})
                targets.push_back(
                    {c + s * (rim[k] - c), "the point s = " + std::to_string(s) + " of spoke " + std::to_string(k)});
        checkNoRayFallsThrough(fan, glm::normalize(Vec3(-0.5f, 0.25f, 1.0f)), targets, dirs, 4.0f, "planar dyadic fan");
    }

    // 2. A folded fan of 64 thin triangles (rim heights 0, 0.01, 0.02), float trigonometry:
    //    rays at the centre and at points along the shared spokes, from both sides.
    {
        const Vec3 c(0.123f, -4.56f, 7.89f);
        std::vector<Vec3> rim;
        for (int k = 0; k < 64; ++k) {
            const float a = 2.0f * ps::kPi * k / 64;
            rim.push_back(c + Vec3(std::cos(a), std::sin(a), 0.01f * (k % 3)));
        }
        Mesh fan;
        for (size_t k = 0; k < rim.size(); ++k) fan.push_back({c, rim[k], rim[(k + 1) % rim.size()]});
        std::vector<Target> targets = {{c, "the fan's centre vertex"}};
        for (size_t k = 0; k < rim.size(); ++k)
            for (float s : {0.01f, 0.3f, 0.8f})
                targets.push_back(
                    {c + s * (rim[k] - c), "the point s = " + std::to_string(s) + " of spoke " + std::to_string(k)});
        // Not within ~11 degrees of the plane: the fold's slope is up to 0.02 per unit.
        std::vector<Vec3> steep;
        for (const Vec3& d : dirs)
            if (std::abs(d.z) > 0.2f) steep.push_back(d);
        checkNoRayFallsThrough(fan, Vec3(0, 0, 1), targets, steep, 3.0f, "folded 64-triangle fan");
    }
}

TEST_CASE("rays: watertight: rays through the shared edges and vertices of a mesh grid never fall through [2 pts]") {
    ps::Rng rng(ps::testseed::seed(10));
    const std::vector<Vec3> dirs = testDirections(20, rng);

    // 1. An 8x8 grid over [-1, 1]^2 (step 1/4) in a tilted plane, all dyadic; the diagonal of
    //    each square alternates, and every other triangle is wound the other way. Targets: every
    //    interior vertex and three dyadic points of every interior edge.
    {
        const int n = 8;
        const float h = 0.25f, z0 = 0.75f;
        const auto V = [&](int i, int j) { return onTiltedPlane(-1.0f + h * i, -1.0f + h * j, z0); };
        Mesh grid;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const Vec3 a = V(i, j), b = V(i + 1, j), c = V(i + 1, j + 1), d = V(i, j + 1);
                Triangle t1, t2;
                if ((i + j) % 2 == 0) {
                    t1 = {a, b, c};
                    t2 = {a, c, d};
                } else {
                    t1 = {a, b, d};
                    t2 = {b, c, d};
                }
                std::swap(t2.p1, t2.p2);
                grid.push_back(t1);
                grid.push_back(t2);
            }
        std::vector<Target> targets;
        const auto edgePoints = [&](const Vec3& a, const Vec3& b, const std::string& name) {
            for (float s : {0.25f, 0.5f, 0.75f})
                targets.push_back({a + s * (b - a), name + " at s = " + std::to_string(s)});
        };
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                const std::string ij = "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
                if (i > 0 && i < n && j > 0 && j < n) targets.push_back({V(i, j), "grid vertex " + ij});
                if (i < n && j > 0 && j < n) edgePoints(V(i, j), V(i + 1, j), "the horizontal edge from vertex " + ij);
                if (j < n && i > 0 && i < n) edgePoints(V(i, j), V(i, j + 1), "the vertical edge from vertex " + ij);
                if (i < n && j < n) {
                    if ((i + j) % 2 == 0) edgePoints(V(i, j), V(i + 1, j + 1), "the diagonal edge from vertex " + ij);
                    else edgePoints(V(i + 1, j), V(i, j + 1), "the diagonal edge of the square at " + ij);
                }
            }
        checkNoRayFallsThrough(grid, glm::normalize(Vec3(-0.5f, 0.25f, 1.0f)), targets, dirs, 4.0f,
                               "tilted dyadic 8x8 grid");
    }

    // 2. A 16x16 grid at an awkward offset and spacing (no coordinate is dyadic), at z = 0.29:
    //    every interior vertex and a random point of every edge leaving it, random directions
    //    from above and below.
    {
        const int n = 16;
        const float x0 = -0.37f, y0 = 1.13f, h = 0.0713f, z = 0.29f;
        const auto V = [&](int i, int j) { return Vec3(x0 + i * h, y0 + j * h, z); };
        Mesh grid;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                grid.push_back({V(i, j), V(i + 1, j), V(i + 1, j + 1)});
                grid.push_back({V(i, j), V(i + 1, j + 1), V(i, j + 1)});
            }
        std::vector<Target> targets;
        for (int j = 1; j < n; ++j)
            for (int i = 1; i < n; ++i) {
                const std::string ij = "(" + std::to_string(i) + ", " + std::to_string(j) + ")";
                const Vec3 v = V(i, j);
                const float s = rng.uniform();
                targets.push_back({v, "grid vertex " + ij});
                targets.push_back({v + s * (V(i + 1, j) - v), "the horizontal edge from vertex " + ij});
                targets.push_back({v + s * (V(i, j + 1) - v), "the vertical edge from vertex " + ij});
                targets.push_back({v + s * (V(i + 1, j + 1) - v), "the diagonal edge from vertex " + ij});
            }
        std::vector<Vec3> random;
        for (int k = 0; k < 12; ++k)
            random.push_back(directionWithCos(Vec3(0, 0, k % 2 ? 1.0f : -1.0f), 0.05f + 0.95f * rng.uniform(), rng));
        checkNoRayFallsThrough(grid, Vec3(0, 0, 1), targets, random, 2.0f, "16x16 grid at z = 0.29");
    }
}
