// Tests of framework/geometry.h and ray.h: the watertight triangle test, the sphere test and
// scale-aware ray offsets (offsetRayOrigin).
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <vector>
#include "geometry.h"
#include "rng.h"
#include "seed.h"

using namespace ps;

namespace {

using Mesh = std::vector<Triangle>;

Vec3 randomUnit(Rng& rng) {
    const float z = 1.0f - 2.0f * rng.uniform(), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * rng.uniform();
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

// A unit direction making the angle with cosine `c` with n (c < 0: the other side).
Vec3 directionWithCos(const Vec3& n, float c, Rng& rng) {
    const float s = std::sqrt(std::max(0.0f, 1.0f - c * c)), phi = 2.0f * kPi * rng.uniform();
    return glm::normalize(Frame(n).toWorld(Vec3(s * std::cos(phi), s * std::sin(phi), c)));
}

// Hit distances of a ray against every triangle of a mesh (no acceleration structure).
std::vector<float> allHits(const Mesh& mesh, const Ray& ray) {
    const WatertightRay wr(ray);
    std::vector<float> ts;
    for (const Triangle& tri : mesh) {
        float t, b1, b2;
        if (intersectTriangle(ray, wr, tri, t, b1, b2)) ts.push_back(t);
    }
    return ts;
}

bool hitsAny(const Mesh& mesh, const Ray& ray) { return !allHits(mesh, ray).empty(); }

// A closed convex octahedron with semi-axes a, rotated by `rot` (columns) and moved to c,
// all in float so its vertices are not "nice" numbers. Faces wound outward.
Mesh octahedron(const Vec3& a, const glm::mat3& rot, const Vec3& c) {
    const Vec3 px = c + rot * Vec3(a.x, 0, 0), nx = c + rot * Vec3(-a.x, 0, 0);
    const Vec3 py = c + rot * Vec3(0, a.y, 0), ny = c + rot * Vec3(0, -a.y, 0);
    const Vec3 pz = c + rot * Vec3(0, 0, a.z), nz = c + rot * Vec3(0, 0, -a.z);
    return {{px, py, pz}, {py, nx, pz}, {nx, ny, pz}, {ny, px, pz},
            {py, px, nz}, {nx, py, nz}, {ny, nx, nz}, {px, ny, nz}};
}

glm::mat3 randomRotation(Rng& rng) {
    const Vec3 z = randomUnit(rng);
    const Frame f(z);
    return glm::mat3(f.s, f.t, f.n);
}

// A flat n x n grid of squares (two triangles each) over [x0, x0+n*h] x [y0, y0+n*h] at z.
Mesh grid(int n, float x0, float y0, float h, float z) {
    Mesh m;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const Vec3 a(x0 + i * h, y0 + j * h, z), b(x0 + (i + 1) * h, y0 + j * h, z);
            const Vec3 c(x0 + (i + 1) * h, y0 + (j + 1) * h, z), d(x0 + i * h, y0 + (j + 1) * h, z);
            m.push_back({a, b, c});
            m.push_back({a, c, d});
        }
    return m;
}

// The point of a triangle at barycentrics (b1, b2), computed in float the way Scene does.
Vec3 pointAt(const Triangle& t, float b1, float b2) { return (1.0f - b1 - b2) * t.p0 + b1 * t.p1 + b2 * t.p2; }

}  // namespace

TEST_CASE("geometry: triangle hit distance and barycentrics equal their exact values") {
    // Axis-aligned case: every quantity is exactly representable, so equality is exact.
    const Triangle tri{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    {
        const Ray ray(Vec3(0.25f, 0.5f, 2.0f), Vec3(0, 0, -1));
        float t = -1, b1 = -1, b2 = -1;
        REQUIRE(intersectTriangle(ray, WatertightRay(ray), tri, t, b1, b2));
        CHECK_MESSAGE(t == 2.0f, "t: expected 2, got " << t);
        CHECK_MESSAGE(b1 == 0.25f, "b1: expected 0.25, got " << b1);
        CHECK_MESSAGE(b2 == 0.5f, "b2: expected 0.5, got " << b2);
    }
    // Oblique rays to known points of a general triangle: t = |p - o| and (b1, b2) as chosen,
    // to 1e-5 (relative for t). The float origin and direction are off by ~2^-24 relative,
    // which moves the hit point by ~|p - o| 2^-24 / |cos|; |cos| >= 0.2 keeps that < 3e-6.
    Rng rng(testseed::seed(11));
    const Triangle g{Vec3(0.3f, -1.2f, 0.7f), Vec3(2.1f, 0.4f, -0.3f), Vec3(-0.5f, 1.9f, 1.1f)};
    for (int i = 0; i < 1000; ++i) {
        const double e1 = 0.02 + 0.96 * rng.uniform(), e2 = (1.0 - e1) * (0.02 + 0.96 * rng.uniform());
        const glm::dvec3 p = (1.0 - e1 - e2) * glm::dvec3(g.p0) + e1 * glm::dvec3(g.p1) + e2 * glm::dvec3(g.p2);
        const Vec3 side = directionWithCos(g.normal(), (i % 2 ? 1.0f : -1.0f) * (0.2f + 0.8f * rng.uniform()), rng);
        const Vec3 o = Vec3(p) + (1.0f + 4.0f * rng.uniform()) * side;
        const glm::dvec3 dd = p - glm::dvec3(o);
        const Ray ray(o, Vec3(glm::normalize(dd)));
        float t, b1, b2;
        const bool hit = intersectTriangle(ray, WatertightRay(ray), g, t, b1, b2);
        INFO("ray " << i << " aimed at barycentrics (" << e1 << ", " << e2 << ")");
        REQUIRE(hit);
        CHECK_MESSAGE(std::abs(t - glm::length(dd)) < 1e-5 * glm::length(dd),
                      "t: expected " << glm::length(dd) << ", got " << t);
        CHECK_MESSAGE(std::abs(b1 - e1) < 1e-5, "b1: expected " << e1 << ", got " << b1);
        CHECK_MESSAGE(std::abs(b2 - e2) < 1e-5, "b2: expected " << e2 << ", got " << b2);
    }
}

TEST_CASE("geometry: triangle respects the open segment (0, tMax) and parallel rays miss") {
    const Triangle tri{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 1, 0)};
    float t, b1, b2;
    Ray r(Vec3(0, 0, 1), Vec3(0, 0, -1), 1.0f);  // hit exactly at tMax: outside the open segment
    CHECK_FALSE(intersectTriangle(r, WatertightRay(r), tri, t, b1, b2));
    r.tMax = 1.0001f;
    CHECK(intersectTriangle(r, WatertightRay(r), tri, t, b1, b2));
    Ray behind(Vec3(0, 0, -1), Vec3(0, 0, -1));  // triangle behind the origin
    CHECK_FALSE(intersectTriangle(behind, WatertightRay(behind), tri, t, b1, b2));
    Ray inPlane(Vec3(-5, 0, 0), Vec3(1, 0, 0));  // in the triangle's plane: det = 0
    CHECK_FALSE(intersectTriangle(inPlane, WatertightRay(inPlane), tri, t, b1, b2));
    Ray onOrigin(Vec3(0, 0, 0), Vec3(0, 0, 1));  // starts on the triangle: t = 0 is excluded
    CHECK_FALSE(intersectTriangle(onOrigin, WatertightRay(onOrigin), tri, t, b1, b2));
}

TEST_CASE("geometry: rays through shared edges and vertices of a closed mesh never slip through") {
    // A closed convex octahedron (random size, rotation, position): every ray from outside
    // aimed at a point on an edge or at a vertex enters and leaves, so it must hit >= 1
    // triangle at entry and >= 1 at exit; a ray through an interior face point hits exactly 2.
    Rng rng(testseed::seed(7));
    for (int mesh = 0; mesh < 20; ++mesh) {
        const Vec3 a{0.5f + rng.uniform(), 0.5f + rng.uniform(), 0.5f + rng.uniform()};
        const float scale = std::pow(10.0f, -3.0f + 6.0f * rng.uniform());
        const Vec3 c = (2.0f * rng.uniform() - 1.0f) * scale * Vec3(3, -2, 1);
        const Mesh m = octahedron(scale * a, randomRotation(rng), c);
        Vec3 centroid(0.0f);
        for (const Triangle& t : m) centroid += (t.p0 + t.p1 + t.p2) / 24.0f;
        for (int k = 0; k < 600; ++k) {
            const Triangle& tri = m[rng.nextU32() % m.size()];
            const Vec3 e0 = tri.p0, e1 = tri.p1, e2 = tri.p2;
            Vec3 target;
            const int kind = k % 3;  // 0: point on an edge, 1: a vertex, 2: a face interior
            if (kind == 0) {
                const float s = rng.uniform();
                target = (1.0f - s) * e0 + s * e1;
            } else if (kind == 1) target = e2;
            else {
                const float u1 = rng.uniform(), u2 = rng.uniform();
                target = pointAt(tri, 0.1f + 0.3f * u1, 0.1f + 0.3f * u2);
            }
            // Origin outside, on the side the face looks to, direction through the target and
            // on into the interior (towards a random point near the centroid).
            const Vec3 inside = centroid + 0.2f * scale * (Vec3{rng.uniform(), rng.uniform(), rng.uniform()} - 0.5f);
            const Vec3 d = glm::normalize(inside - target);
            const Ray ray(target - 3.0f * scale * d, d);
            const std::vector<float> ts = allHits(m, ray);
            const float tMid = glm::dot(inside - ray.o, d);  // the ray is inside the mesh here
            int entry = 0, exit = 0;
            for (float t : ts) (t < tMid ? entry : exit)++;
            INFO("mesh " << mesh << " (scale " << scale << "), ray " << k << ", kind " << kind);
            CHECK_MESSAGE(entry >= 1, "expected >= 1 hit entering the mesh, got " << entry);
            CHECK_MESSAGE(exit >= 1, "expected >= 1 hit leaving the mesh, got " << exit);
            if (kind == 2) CHECK_MESSAGE(ts.size() == 2, "interior point: expected exactly 2 hits, got " << ts.size());
        }
    }
}

TEST_CASE("geometry: rays at the vertices and edges of a grid and of a thin fan hit >= 1 triangle") {
    Rng rng(testseed::seed(3));
    // A 16x16 grid at an awkward offset and spacing: aim at every interior vertex and at a point
    // of every interior edge, from random directions above and below.
    const Mesh g = grid(16, -0.37f, 1.13f, 0.0713f, 0.29f);
    int misses = 0, rays = 0;
    for (int j = 1; j < 16; ++j)
        for (int i = 1; i < 16; ++i) {
            const Vec3 v(-0.37f + i * 0.0713f, 1.13f + j * 0.0713f, 0.29f);
            const Vec3 targets[] = {v, v + Vec3(0.0713f * rng.uniform(), 0, 0), v + Vec3(0, 0.0713f * rng.uniform(), 0),
                                    v + 0.0713f * rng.uniform() * Vec3(1, 1, 0)};  // the diagonal edge
            for (const Vec3& target : targets)
                for (int s = 0; s < 4; ++s) {
                    const Vec3 d =
                        directionWithCos(Vec3(0, 0, s % 2 ? 1.0f : -1.0f), 0.05f + 0.95f * rng.uniform(), rng);
                    const Ray ray(target + 2.0f * d, -d);
                    ++rays;
                    if (!hitsAny(g, ray)) {
                        ++misses;
                        if (misses < 5)
                            FAIL_CHECK("ray aimed at (" << target.x << ", " << target.y << ", " << target.z
                                                        << ") from direction " << d.x << " " << d.y << " " << d.z
                                                        << " missed every triangle");
                    }
                }
        }
    CHECK_MESSAGE(misses == 0, "expected 0 of " << rays << " rays through grid vertices/edges to miss, got " << misses);

    // A fan of 64 thin triangles around a centre vertex: rays aimed at the centre.
    const Vec3 centre(0.123f, -4.56f, 7.89f);
    Mesh fan;
    for (int k = 0; k < 64; ++k) {
        const float a0 = 2.0f * kPi * k / 64, a1 = 2.0f * kPi * (k + 1) / 64;
        fan.push_back({centre, centre + Vec3(std::cos(a0), std::sin(a0), 0.01f * (k % 3)),
                       centre + Vec3(std::cos(a1), std::sin(a1), 0.01f * ((k + 1) % 3))});
    }
    fan.back().p2 = fan.front().p1;  // close the fan exactly
    for (int s = 0; s < 2000; ++s) {
        const Vec3 d = directionWithCos(Vec3(0, 0, s % 2 ? 1.0f : -1.0f), 0.05f + 0.95f * rng.uniform(), rng);
        const Ray ray(centre + 3.0f * d, -d);
        if (!hitsAny(fan, ray)) {
            FAIL_CHECK("ray " << s << " aimed at the fan's centre vertex missed all 64 triangles");
            break;
        }
    }
}

TEST_CASE("geometry: rays just outside a triangle's edges miss, just inside hit") {
    // Points moved out of (into) the triangle across an edge by 1e-4 of the edge's length:
    // far more than float rounding (~1e-7 relative), so the answer is unambiguous.
    Rng rng(testseed::seed(5));
    const Triangle tri{Vec3(0.3f, -1.2f, 0.7f), Vec3(2.1f, 0.4f, -0.3f), Vec3(-0.5f, 1.9f, 1.1f)};
    const Vec3 n = tri.normal(), v[3] = {tri.p0, tri.p1, tri.p2};
    for (int i = 0; i < 3000; ++i) {
        const Vec3 a = v[i % 3], b = v[(i + 1) % 3], opposite = v[(i + 2) % 3];
        const float s = 0.01f + 0.98f * rng.uniform();
        const Vec3 onEdge = (1.0f - s) * a + s * b;
        Vec3 out = glm::normalize(glm::cross(b - a, n));     // in-plane, perpendicular to the edge
        if (glm::dot(out, opposite - a) > 0.0f) out = -out;  // pointing away from the triangle
        const float delta = 1e-4f * glm::length(b - a);
        const Vec3 d = directionWithCos(n, (i % 2 ? 1.0f : -1.0f) * (0.1f + 0.9f * rng.uniform()), rng);
        const Ray outside(onEdge + delta * out + 2.0f * d, -d), inside(onEdge - delta * out + 2.0f * d, -d);
        float t, b1, b2;
        INFO("edge " << i % 3 << ", s = " << s);
        CHECK_FALSE(intersectTriangle(outside, WatertightRay(outside), tri, t, b1, b2));
        CHECK(intersectTriangle(inside, WatertightRay(inside), tri, t, b1, b2));
    }
}

TEST_CASE("geometry: a ray offset off a triangle never re-hits it, at scales 1e-4 to 1e4 and far from the origin") {
    // offsetRayOrigin moves the hit point by errScale * 2^-19 along the normal, to the side the
    // new direction points to. Over many random hit points and directions (including grazing
    // ones, |cos| = 1e-3), the new ray must not hit the triangle it leaves (no ignorePrim here).
    struct Config {
        float scale;
        Vec3 shift;
    };
    const Config configs[] = {{1e-4f, Vec3(0)},
                              {1.0f, Vec3(0)},
                              {1e4f, Vec3(0)},
                              {1.0f, Vec3(1e5f, -1e5f, 1e5f)},
                              {1e-4f, Vec3(0.5f, 0.25f, -1.0f)}};
    Rng rng(testseed::seed(17));
    for (const Config& cfg : configs) {
        int rehits = 0, trials = 0;
        for (int tri = 0; tri < 50; ++tri) {
            Triangle t;
            for (Vec3* p : {&t.p0, &t.p1, &t.p2})
                *p = cfg.shift + cfg.scale * (2.0f * Vec3{rng.uniform(), rng.uniform(), rng.uniform()} - 1.0f);
            if (t.area() < 0.05f * cfg.scale * cfg.scale) continue;  // skip slivers
            const Vec3 n = t.normal();
            for (int k = 0; k < 400; ++k) {
                // The hit point as Scene computes it: a ray hits t; p from its barycentrics.
                const float u1 = 0.01f + 0.98f * rng.uniform(), u2 = (1.0f - u1) * (0.01f + 0.98f * rng.uniform());
                const Vec3 aim = pointAt(t, u1, u2);
                const Vec3 din = directionWithCos(n, (k % 2 ? 1.0f : -1.0f) * (0.05f + 0.95f * rng.uniform()), rng);
                const Ray in(aim + 3.0f * cfg.scale * din, -din);
                float th, b1, b2;
                if (!intersectTriangle(in, WatertightRay(in), t, th, b1, b2)) continue;
                const Vec3 p = pointAt(t, b1, b2);
                // Leave: reflected side or transmitted side; half the rays grazing (|cos| = 1e-3).
                const float c = (k % 4 < 2 ? 1e-3f : 0.01f + 0.99f * rng.uniform()) * (k % 3 ? 1.0f : -1.0f);
                const Vec3 w = directionWithCos(n, c, rng);
                const Ray out(offsetRayOrigin(p, n, t.errScale(), w), w);
                ++trials;
                if (intersectTriangle(out, WatertightRay(out), t, th, b1, b2)) {
                    if (++rehits <= 3)
                        FAIL_CHECK("scale " << cfg.scale << " shift " << cfg.shift.x << ": ray leaving with cos " << c
                                            << " re-hit its triangle at t = " << th);
                }
            }
        }
        INFO("scale " << cfg.scale << ", shift (" << cfg.shift.x << ", " << cfg.shift.y << ", " << cfg.shift.z << ")");
        CHECK(trials > 5000);
        CHECK_MESSAGE(rehits == 0, "expected 0 re-hits in " << trials << " rays, got " << rehits);
    }
}

TEST_CASE("geometry: a ray offset off a sphere never re-hits it outward and stays inside inward") {
    // Sphere hit points as Scene computes them (reprojected to the surface, n = outward normal):
    // outward directions (cos > 0, down to 1e-3) must not hit the sphere again; inward
    // directions (a refraction) must hit it from inside.
    struct Config {
        float scale;
        Vec3 shift;
    };
    const Config configs[] = {{1e-4f, Vec3(0)}, {1.0f, Vec3(0)}, {1e4f, Vec3(0)}, {1.0f, Vec3(1e5f, -1e5f, 1e5f)}};
    Rng rng(testseed::seed(23));
    for (const Config& cfg : configs) {
        int failures = 0, trials = 0;
        for (int s = 0; s < 50; ++s) {
            const Sphere sph{cfg.shift + cfg.scale * (2.0f * Vec3{rng.uniform(), rng.uniform(), rng.uniform()} - 1.0f),
                             cfg.scale * (0.5f + rng.uniform())};
            for (int k = 0; k < 200; ++k) {
                const Vec3 n = glm::normalize(sph.center + sph.radius * randomUnit(rng) - sph.center);
                const Vec3 p = sph.center + sph.radius * n;
                const bool outward = k % 2 == 0;
                const float c = (k % 4 < 2 ? 1e-3f : 0.01f + 0.99f * rng.uniform()) * (outward ? 1.0f : -1.0f);
                const Vec3 w = directionWithCos(n, c, rng);
                const Ray ray(offsetRayOrigin(p, n, sph.errScale(), w), w);
                float t;
                const bool hit = intersectSphere(ray, sph, t);
                ++trials;
                if (hit != !outward && ++failures <= 3)
                    FAIL_CHECK("scale " << cfg.scale << ": ray leaving with cos " << c << (outward ? " hit" : " missed")
                                        << " the sphere (t = " << t << ")");
            }
        }
        INFO("scale " << cfg.scale << ", shift " << cfg.shift.x);
        CHECK_MESSAGE(failures == 0, "expected 0 failures in " << trials << " rays, got " << failures);
    }
}

TEST_CASE("geometry: two parallel surfaces 4e-5 apart do not leak") {
    // Lower surface: a grid of triangles at z = 0; upper: a grid at z = 4e-5 (normals up or
    // down). A ray leaving a lower triangle upwards (offset by offsetRayOrigin, scale 1) must
    // hit the upper surface and no lower triangle (including its coplanar neighbours); the same
    // downwards from the upper surface. offset = 2^-19 ~ 1.9e-6 << 4e-5.
    const float gap = 4e-5f;
    const Mesh lower = grid(8, -1.0f, -1.0f, 0.25f, 0.0f);
    Mesh upper = grid(8, -1.0f, -1.0f, 0.25f, gap);
    for (size_t i = 0; i < upper.size(); i += 2) std::swap(upper[i].p1, upper[i].p2);  // mixed windings
    Rng rng(testseed::seed(31));
    int leaks = 0, selfHits = 0, trials = 0;
    for (int k = 0; k < 20000; ++k) {
        const bool up = k % 2 == 0;
        const Mesh& from = up ? lower : upper;
        const Mesh& to = up ? upper : lower;
        const Triangle& tri = from[rng.nextU32() % from.size()];
        const float u1 = rng.uniform(), u2 = rng.uniform();
        const Vec3 p = pointAt(tri, 0.01f + 0.49f * u1, 0.01f + 0.49f * u2);
        if (std::abs(p.x) > 0.9f || std::abs(p.y) > 0.9f) continue;  // keep grazing rays over the grids
        const Vec3 n = tri.normal();
        const float c = k % 4 < 2 ? 1e-3f : 0.01f + 0.99f * rng.uniform();
        const Vec3 w = directionWithCos(Vec3(0, 0, up ? 1.0f : -1.0f), c, rng);
        const Ray ray(offsetRayOrigin(p, n, tri.errScale(), w), w);
        ++trials;
        if (!hitsAny(to, ray)) ++leaks;
        // The surface it leaves must not be hit before the other one.
        const std::vector<float> self = allHits(from, ray), other = allHits(to, ray);
        for (float t : self)
            if (other.empty() || t < *std::min_element(other.begin(), other.end())) {
                ++selfHits;
                break;
            }
    }
    CHECK(trials > 10000);
    CHECK_MESSAGE(leaks == 0, "expected 0 of " << trials << " rays to pass the other surface, got " << leaks);
    CHECK_MESSAGE(selfHits == 0, "expected 0 rays to re-hit the surface they leave, got " << selfHits);
}

TEST_CASE("geometry: sphere intersection from outside, inside, tangent and far away") {
    const Sphere unit{Vec3(1, 2, 3), 2.0f};
    float t = -1;
    SUBCASE("from outside: the near root") {
        const Ray r(Vec3(1, 2, -7), Vec3(0, 0, 1));
        REQUIRE(intersectSphere(r, unit, t));
        CHECK_MESSAGE(t == doctest::Approx(8.0).epsilon(1e-6), "expected t = 8, got " << t);
    }
    SUBCASE("from inside: the far root") {
        const Ray r(Vec3(1, 2, 3), Vec3(0, 0, -1));
        REQUIRE(intersectSphere(r, unit, t));
        CHECK_MESSAGE(t == doctest::Approx(2.0).epsilon(1e-6), "expected t = 2, got " << t);
    }
    SUBCASE("pointing away from outside, and tMax before the sphere: miss") {
        const Ray away(Vec3(1, 2, -7), Vec3(0, 0, -1));
        CHECK_FALSE(intersectSphere(away, unit, t));
        const Ray shortRay(Vec3(1, 2, -7), Vec3(0, 0, 1), 7.9f);
        CHECK_FALSE(intersectSphere(shortRay, unit, t));
    }
    SUBCASE("tangent and just past tangent") {
        // Passing at distance r (tangent): a hit, if reported, lies at the tangent point t = 10.
        const Ray tangent(Vec3(3, 2, -7), Vec3(0, 0, 1));
        if (intersectSphere(tangent, unit, t)) CHECK_MESSAGE(std::abs(t - 10.0f) < 1e-2f, "tangent hit at t = " << t);
        CHECK(std::isfinite(t));
        const Ray past(Vec3(3.001f, 2, -7), Vec3(0, 0, 1));
        CHECK_FALSE(intersectSphere(past, unit, t));
        const Ray before(Vec3(2.999f, 2, -7), Vec3(0, 0, 1));
        CHECK(intersectSphere(before, unit, t));
    }
    SUBCASE("radius 1e-3 at distance 1e3, radius 0.5 at distance 1e5") {
        // The naive quadratic b^2 - c loses all digits here (b^2 ~ 1e6, r^2 = 1e-6); the
        // Hearn-Baker form computes the closest approach directly. Rays passing at 0.5 r must
        // hit, at 1.5 r must miss (the closest approach is computed to ~ulp(1e3) = 6e-5 = 0.06 r).
        // t must be within 8 ulp(distance) of the double-precision value.
        Rng rng(testseed::seed(41));
        for (float dist : {1e3f, 1e5f}) {
            const float r = dist == 1e3f ? 1e-3f : 0.5f;  // at 1e5, ulp = 0.0078: r = 0.5 keeps 0.06 r margins
            for (int k = 0; k < 500; ++k) {
                const Vec3 dir = randomUnit(rng);
                const Sphere s{dir * (dist * rng.uniform()), r};
                const Vec3 d = randomUnit(rng);
                const Frame f(d);
                const float miss = k % 3 == 0 ? 0.0f : (k % 3 == 1 ? 0.5f : 1.5f);
                const Vec3 o = s.center - dist * d + miss * r * f.s;
                const Ray ray(o, d);
                const bool hit = intersectSphere(ray, s, t);
                INFO("distance " << dist << ", ray " << k << ", passing at " << miss << " r");
                if (miss > 1.0f) {
                    CHECK_FALSE(hit);
                    continue;
                }
                REQUIRE(hit);
                const glm::dvec3 fo = glm::dvec3(o) - glm::dvec3(s.center), dd = glm::dvec3(d);
                const double b = glm::dot(fo, dd), l2 = glm::dot(fo - b * dd, fo - b * dd);
                const double tRef = -b - std::sqrt(double(r) * r - l2);
                const double tol = 8.0 * std::ldexp(1.0, std::ilogb(dist) - 23);
                CHECK_MESSAGE(std::abs(t - tRef) < tol, "expected t = " << tRef << " +- " << tol << ", got " << t);
            }
        }
    }
    SUBCASE("huge sphere seen from close by") {
        // Radius 1e4, origin 1 above the surface: t = 1 to 1e-3 (c = |f|^2 - r^2 loses
        // ~ulp(1e8) / 2e4 = 4e-4 relative).
        const Sphere big{Vec3(0, 0, -1e4f), 1e4f};
        const Ray r(Vec3(0, 0, 1), Vec3(0, 0, -1));
        REQUIRE(intersectSphere(r, big, t));
        CHECK_MESSAGE(std::abs(t - 1.0f) < 1e-3f, "expected t = 1, got " << t);
        const Ray inside(Vec3(0, 0, -1), Vec3(0, 0, 1));  // just inside: t = 1 to the surface above
        REQUIRE(intersectSphere(inside, big, t));
        CHECK_MESSAGE(std::abs(t - 1.0f) < 1e-3f, "from inside: expected t = 1, got " << t);
    }
}
