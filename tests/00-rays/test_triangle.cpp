// Lesson 0, graded: the watertight ray/triangle test (WatertightRay and intersectTriangle,
// Eq. 0.3 to 0.6 of lessons/00-rays/README.md) on single triangles: the per-ray constants, exact
// hits, edges, both windings, parallel rays and the open segment (0, tMax).
#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>
#include "lesson00.h"
#include "seed.h"

using namespace lesson00;

namespace {

// A triangle in the plane z = 2 with dyadic corners and 2*area = 8 (a power of two), so that
// for rays along the z axis every quantity of Eq. 0.3 to 0.6 is exact in float.
const Triangle kFlat{Vec3(-1, -0.5f, 2), Vec3(3, -0.5f, 2), Vec3(-1, 1.5f, 2)};
// A triangle in a tilted plane (normal (-2, 1, 4)), dyadic corners.
const Triangle kTilted{Vec3(0, 0, 0), Vec3(2, 0, 1), Vec3(0, 2, -0.5f)};
// A general triangle: no coordinate is "nice".
const Triangle kGeneral{Vec3(0.3f, -1.2f, 0.7f), Vec3(2.1f, 0.4f, -0.3f), Vec3(-0.5f, 1.9f, 1.1f)};

// Checks a hit with t within relTolT (relative) and barycentrics within tolB of the expected.
bool expectHit(const Ray& ray, const Triangle& tri, double t, double b1, double b2, double relTolT, double tolB,
               const std::string& what, Tally& tally) {
    const Hit h = intersect(ray, tri);
    const bool ok = h.hit && std::abs(h.t - t) <= relTolT * std::abs(t) && std::abs(h.b1 - b1) <= tolB &&
                    std::abs(h.b2 - b2) <= tolB;
    if (tally.fail(ok))
        FAIL_CHECK(what << "\n  " << str(ray) << "\n  " << str(tri) << "\n  expected a hit at t = " << t
                        << " with b1 = " << b1 << ", b2 = " << b2 << " (tolerances: t relative " << relTolT << ", b "
                        << tolB << ")\n  got " << str(h));
    return ok;
}

bool expectMiss(const Ray& ray, const Triangle& tri, const std::string& what, Tally& tally) {
    const Hit h = intersect(ray, tri);
    if (tally.fail(!h.hit))
        FAIL_CHECK(what << "\n  " << str(ray) << "\n  " << str(tri) << "\n  expected no hit, got " << str(h));
    return !h.hit;
}

// Parity of the permutation (kx, ky, kz) of (0, 1, 2): true if even (a rotation).
bool evenPermutation(int kx, int ky, int kz) {
    return (kx == 0 && ky == 1 && kz == 2) || (kx == 1 && ky == 2 && kz == 0) || (kx == 2 && ky == 0 && kz == 1);
}

}  // namespace

TEST_CASE("rays: WatertightRay picks the dominant axis kz and the shear that maps d to +z keeping orientation [1 pt]") {
    // Eq. 0.3: kz = the axis of the largest |d| component; (kx, ky, kz) a permutation of the axes;
    // Sx = d[kx] / d[kz], Sy = d[ky] / d[kz], Sz = 1 / d[kz], so the sheared direction is (0, 0, 1);
    // and the map keeps orientation: (kx, ky, kz) is a rotation of (x, y, z) when d[kz] > 0 and
    // one swap away from it when d[kz] < 0.
    std::vector<Vec3> dirs = {Vec3(1, 0, 0),
                              Vec3(-1, 0, 0),
                              Vec3(0, 1, 0),
                              Vec3(0, -1, 0),
                              Vec3(0, 0, 1),
                              Vec3(0, 0, -1),
                              glm::normalize(Vec3(0.3f, -0.8f, 0.5f)),
                              glm::normalize(Vec3(-0.9f, 0.2f, 0.1f)),
                              glm::normalize(Vec3(0.1f, 0.2f, -0.95f)),
                              glm::normalize(Vec3(-0.6f, 0.0f, 0.8f))};
    ps::Rng rng(ps::testseed::seed(3));
    while (dirs.size() < 1000) {
        const Vec3 d = randomUnit(rng);
        Vec3 a = glm::abs(d);
        std::sort(&a[0], &a[0] + 3);
        if (a[2] - a[1] > 1e-3f) dirs.push_back(d);  // a unique largest component
    }
    Tally tally;
    for (const Vec3& d : dirs) {
        const ps::WatertightRay wr(Ray(Vec3(0.5f, -2, 3), d));
        const Vec3 a = glm::abs(d);
        const int kzExpected = (a.x > a.y && a.x > a.z) ? 0 : (a.y > a.z ? 1 : 2);
        std::ostringstream why;
        why.precision(9);
        const bool perm = wr.kx >= 0 && wr.kx < 3 && wr.ky >= 0 && wr.ky < 3 && wr.kz >= 0 && wr.kz < 3 &&
                          wr.kx != wr.ky && wr.ky != wr.kz && wr.kx != wr.kz;
        if (!perm) {
            why << "(kx, ky, kz) = (" << wr.kx << ", " << wr.ky << ", " << wr.kz
                << ") is not a permutation of (0, 1, 2)";
        } else if (wr.kz != kzExpected) {
            why << "expected kz = " << kzExpected << " (the largest |d| component), got kz = " << wr.kz;
        } else {
            const double dz = d[wr.kz], sx = d[wr.kx] / dz, sy = d[wr.ky] / dz, sz = 1.0 / dz;
            if (std::abs(wr.Sx - sx) > 1e-6 || std::abs(wr.Sy - sy) > 1e-6 ||
                std::abs(wr.Sz - sz) > 1e-6 * std::abs(sz))
                why << "with (kx, ky, kz) = (" << wr.kx << ", " << wr.ky << ", " << wr.kz
                    << "): expected (Sx, Sy, Sz) = (" << sx + 0.0 << ", " << sy + 0.0 << ", " << sz << "), got ("
                    << wr.Sx << ", " << wr.Sy << ", " << wr.Sz << ")";
            else if (evenPermutation(wr.kx, wr.ky, wr.kz) != (dz > 0.0))
                why << "(kx, ky, kz) = (" << wr.kx << ", " << wr.ky << ", " << wr.kz << ") with d[kz] "
                    << (dz > 0 ? "> 0" : "< 0") << " flips orientation: swap kx and ky exactly when d[kz] < 0";
        }
        if (tally.fail(why.str().empty())) FAIL_CHECK("direction d = " << str(d) << ": " << why.str());
    }
    LESSON00_SUMMARY(tally, "directions' constants");
}

TEST_CASE("rays: triangle hits report the exact t and barycentrics [2 pts]") {
    Tally tally;
    // 1. Rays along +-z to dyadic points of kFlat: every value is exact in float (up to the
    //    order of operations: 4 ulps allowed).
    const double ulp4 = 4.0 * 0x1p-24;
    const double bs[][2] = {{0.25, 0.5}, {0.125, 0.125}, {0.5, 0.25}, {0.75, 0.125}, {0.0625, 0.875}};
    for (const auto& b : bs)
        for (float L : {1.0f, 3.5f, 1024.0f})
            for (float side : {1.0f, -1.0f}) {
                const Vec3 p(-1.0f + 4.0f * float(b[0]), -0.5f + 2.0f * float(b[1]), 2.0f);
                const Ray ray(p + Vec3(0, 0, side * L), Vec3(0, 0, -side));
                expectHit(ray, kFlat, L, b[0], b[1], ulp4, ulp4, "a ray along the z axis to a dyadic point", tally);
            }
    // 2. Rays along each axis (+-x, +-y, +-z) to dyadic points of the tilted triangle.
    const double tb[][2] = {{0.25, 0.5}, {0.375, 0.125}, {0.125, 0.75}};
    for (const auto& b : tb) {
        const Vec3 p = kTilted.p0 + float(b[0]) * (kTilted.p1 - kTilted.p0) + float(b[1]) * (kTilted.p2 - kTilted.p0);
        for (int axis = 0; axis < 3; ++axis)
            for (float side : {1.0f, -1.0f}) {
                Vec3 d(0.0f);
                d[axis] = side;
                const Ray ray(p - 2.5f * d, d);
                expectHit(ray, kTilted, 2.5, b[0], b[1], 1e-6, 1e-6,
                          "a ray along a coordinate axis to a tilted triangle", tally);
            }
    }
    // 3. Oblique rays from both sides to known points of a general triangle: t = |p - o| and
    //    (b1, b2) as chosen, to 1e-5. (The float origin and direction move the true hit by
    //    ~|p - o| 2^-24 / |cos|; |cos| >= 0.2 keeps that < 3e-6.)
    ps::Rng rng(ps::testseed::seed(4));
    for (int i = 0; i < 1000; ++i) {
        const double e1 = 0.02 + 0.96 * rng.uniform(), e2 = (1.0 - e1) * (0.02 + 0.96 * rng.uniform());
        const DVec3 p = (1.0 - e1 - e2) * DVec3(kGeneral.p0) + e1 * DVec3(kGeneral.p1) + e2 * DVec3(kGeneral.p2);
        const Vec3 side =
            directionWithCos(kGeneral.normal(), (i % 2 ? 1.0f : -1.0f) * (0.2f + 0.8f * rng.uniform()), rng);
        const Vec3 o = Vec3(p) + (1.0f + 4.0f * rng.uniform()) * side;
        const DVec3 dd = p - DVec3(o);
        const Ray ray(o, Vec3(glm::normalize(dd)));
        expectHit(ray, kGeneral, glm::length(dd), e1, e2, 1e-5, 1e-5, "an oblique ray to a known point", tally);
    }
    LESSON00_SUMMARY(tally, "hits");
}

TEST_CASE("rays: rays just beside each edge miss and rays just inside hit [1 pt]") {
    // Points moved out of (into) the triangle across an edge by 1e-4 of the edge's length: far
    // more than float rounding, so the answer is unambiguous. Rays from both sides.
    ps::Rng rng(ps::testseed::seed(5));
    Tally tally;
    for (const Triangle& tri : {kGeneral, kTilted, kFlat}) {
        const Vec3 n = tri.normal(), v[3] = {tri.p0, tri.p1, tri.p2};
        for (int i = 0; i < 600; ++i) {
            const Vec3 a = v[i % 3], b = v[(i + 1) % 3], opposite = v[(i + 2) % 3];
            const float s = 0.01f + 0.98f * rng.uniform();
            const Vec3 onEdge = (1.0f - s) * a + s * b;
            Vec3 out = glm::normalize(glm::cross(b - a, n));     // in the plane, across the edge
            if (glm::dot(out, opposite - a) > 0.0f) out = -out;  // away from the triangle
            const float delta = 1e-4f * glm::length(b - a);
            const Vec3 d = directionWithCos(n, (i % 2 ? 1.0f : -1.0f) * (0.1f + 0.9f * rng.uniform()), rng);
            const Ray outside(onEdge + delta * out + 2.0f * d, -d), inside(onEdge - delta * out + 2.0f * d, -d);
            const std::string where =
                "edge p" + std::to_string(i % 3) + "-p" + std::to_string((i + 1) % 3) + " at s = " + std::to_string(s);
            expectMiss(outside, tri, "a ray passing 1e-4 edge lengths OUTSIDE the " + where, tally);
            const ExactHit e = exactHit(inside, tri);
            expectHit(inside, tri, e.t, e.b1, e.b2, 1e-5, 1e-5, "a ray passing 1e-4 edge lengths INSIDE the " + where,
                      tally);
        }
    }
    LESSON00_SUMMARY(tally, "rays");
}

TEST_CASE("rays: back-facing triangles are hit too and both windings give the same hit [1 pt]") {
    // The same ray against (p0, p1, p2) and (p0, p2, p1): both hit at the same t, with b1 and b2
    // exchanged. Rays from the front and from the back.
    ps::Rng rng(ps::testseed::seed(6));
    Tally tally;
    for (int i = 0; i < 400; ++i) {
        Triangle tri;
        do {
            for (Vec3* p : {&tri.p0, &tri.p1, &tri.p2})
                *p = 2.0f * Vec3{rng.uniform(), rng.uniform(), rng.uniform()} - 1.0f;
        } while (tri.area() < 0.1f);
        const Triangle flipped{tri.p0, tri.p2, tri.p1};
        const float e1 = 0.05f + 0.9f * rng.uniform(), e2 = (1.0f - e1) * (0.05f + 0.9f * rng.uniform());
        const Vec3 p = pointAt(tri, e1, e2);
        const bool front = i % 2 == 1;
        const Vec3 d = directionWithCos(tri.normal(), (front ? 1.0f : -1.0f) * (0.2f + 0.8f * rng.uniform()), rng);
        const Ray ray(p + 3.0f * d, -d);
        const ExactHit e = exactHit(ray, tri);
        expectHit(ray, tri, e.t, e.b1, e.b2, 1e-5, 1e-5,
                  std::string("winding (p0, p1, p2), seen from the ") + (front ? "front" : "back"), tally);
        expectHit(
            ray, flipped, e.t, e.b2, e.b1, 1e-5, 1e-5,
            std::string("winding (p0, p2, p1) (b1 and b2 exchanged), seen from the ") + (front ? "back" : "front"),
            tally);
    }
    LESSON00_SUMMARY(tally, "hits");
}

TEST_CASE("rays: rays parallel to the triangle's plane miss and slightly tilted rays hit [1 pt]") {
    // kFlat lies in z = 2. Directions with d.z = 0 exactly, in the plane (through the triangle)
    // and 1e-3 above and below it: every one misses. The same origins aimed at an interior
    // point: hits.
    const Vec3 dirs[] = {Vec3(1, 0, 0), Vec3(0, -1, 0), glm::normalize(Vec3(3, 4, 0)), glm::normalize(Vec3(-4, 3, 0)),
                         glm::normalize(Vec3(-1, -1, 0))};
    const Vec3 interior = pointAt(kFlat, 0.25f, 0.25f);
    Tally tally;
    for (const Vec3& d : dirs)
        for (float dz : {0.0f, 1e-3f, -1e-3f}) {
            const Ray ray(interior - 5.0f * d + Vec3(0, 0, dz), d);
            expectMiss(
                ray, kFlat,
                dz == 0.0f ? "a ray in the triangle's plane, through it" : "a ray parallel to the plane, 1e-3 off it",
                tally);
            if (dz != 0.0f) {
                const Ray tilted(ray.o, glm::normalize(interior - ray.o));  // tilted by ~2e-4 rad
                // At this grazing angle float rounding of the direction moves the hit by ~1e-3:
                // the expected values are those of the float ray, computed exactly.
                const ExactHit e = exactHit(tilted, kFlat);
                expectHit(tilted, kFlat, e.t, e.b1, e.b2, 1e-4, 1e-4,
                          "the same origin, aimed at the interior point (b1, b2) = (0.25, 0.25)", tally);
            }
        }
    LESSON00_SUMMARY(tally, "rays");
}

TEST_CASE("rays: a hit counts only strictly inside the open segment (0, tMax) [1 pt]") {
    Tally tally;
    // Exact case: the hit is at t = 2 exactly (kFlat, ray along -z).
    const Vec3 p = pointAt(kFlat, 0.25f, 0.5f);
    Ray ray(p + Vec3(0, 0, 2), Vec3(0, 0, -1));
    ray.tMax = 2.0f;
    expectMiss(ray, kFlat, "hit exactly at t = tMax = 2: not inside the open segment (0, tMax)", tally);
    ray.tMax = 1.5f;
    expectMiss(ray, kFlat, "hit at t = 2 beyond tMax = 1.5", tally);
    ray.tMax = std::nextafter(2.0f, 3.0f);
    expectHit(ray, kFlat, 2.0, 0.25, 0.5, 1e-7, 1e-7, "hit at t = 2 one float below tMax", tally);
    ray.tMax = ps::kInf;
    expectHit(ray, kFlat, 2.0, 0.25, 0.5, 1e-7, 1e-7, "hit at t = 2, tMax = infinity", tally);
    // Oblique rays: tMax 1e-4 (relative) beyond the hit: a hit; 1e-4 before it: a miss.
    ps::Rng rng(ps::testseed::seed(7));
    for (int i = 0; i < 300; ++i) {
        const float e1 = 0.05f + 0.9f * rng.uniform(), e2 = (1.0f - e1) * (0.05f + 0.9f * rng.uniform());
        const Vec3 q = pointAt(kGeneral, e1, e2);
        const Vec3 d = directionWithCos(kGeneral.normal(), (i % 2 ? 1.0f : -1.0f) * (0.2f + 0.8f * rng.uniform()), rng);
        Ray r(q + (0.5f + 10.0f * rng.uniform()) * d, -d);
        const ExactHit e = exactHit(r, kGeneral);
        r.tMax = float(e.t * (1.0 + 1e-4));
        expectHit(r, kGeneral, e.t, e.b1, e.b2, 1e-5, 1e-5, "tMax 1e-4 beyond the hit", tally);
        r.tMax = float(e.t * (1.0 - 1e-4));
        expectMiss(r, kGeneral, "tMax 1e-4 before the hit", tally);
    }
    LESSON00_SUMMARY(tally, "rays");
}

TEST_CASE("rays: triangles behind the origin are missed and the reversed ray hits [1 pt]") {
    Tally tally;
    const Vec3 p = pointAt(kFlat, 0.25f, 0.5f);
    // Behind at t = -3: miss; the reversed ray: hit at t = 3. Origins on the triangle (t = 0): miss.
    expectMiss(Ray(p + Vec3(0, 0, 3), Vec3(0, 0, 1)), kFlat, "the triangle lies behind the origin, at t = -3", tally);
    expectHit(Ray(p + Vec3(0, 0, 3), Vec3(0, 0, -1)), kFlat, 3.0, 0.25, 0.5, 1e-7, 1e-7, "the reversed ray", tally);
    expectMiss(Ray(p, Vec3(0, 0, -1)), kFlat, "the origin is on the triangle: t = 0 is not in (0, tMax)", tally);
    expectMiss(Ray(p, Vec3(0, 0, 1)), kFlat, "the origin is on the triangle: t = 0 is not in (0, tMax)", tally);
    {
        // A hit closer than any float: the corner a lies the smallest positive float d above the
        // origin's plane, the others in it, and the ray meets the triangle where a's weight is 1/4,
        // at t = d / 4, which rounds to 0 in float (every product of Eq. 0.6 is exact here: 2*area
        // = 64, T = 16 d). Whatever the test returns, a hit must have t > 0.
        const float d = std::numeric_limits<float>::denorm_min();
        const Triangle nearly{Vec3(-1, -1, d), Vec3(7, -1, 0), Vec3(-1, 7, 0)};
        const Ray up(Vec3(2, 2, 0), Vec3(0, 0, 1));
        const Hit h = intersect(up, nearly);
        if (tally.fail(!h.hit || h.t > 0.0f))
            FAIL_CHECK(
                "a hit at t = 3.5e-46, below the smallest positive float: expected no hit or a hit with t > 0\n  "
                << str(up) << "\n  " << str(nearly) << "\n  got " << str(h)
                << " (t = T / det rounds to 0 here: is t itself checked against (0, tMax)?)");
    }
    ps::Rng rng(ps::testseed::seed(8));
    for (int i = 0; i < 300; ++i) {
        const float e1 = 0.05f + 0.9f * rng.uniform(), e2 = (1.0f - e1) * (0.05f + 0.9f * rng.uniform());
        const Vec3 q = pointAt(kGeneral, e1, e2);
        const Vec3 d = directionWithCos(kGeneral.normal(), (i % 2 ? 1.0f : -1.0f) * (0.2f + 0.8f * rng.uniform()), rng);
        const Vec3 o = q + (0.5f + 10.0f * rng.uniform()) * d;
        expectMiss(Ray(o, d), kGeneral, "pointing away from the triangle (the plane is at negative t)", tally);
        const Ray towards(o, -d);
        const ExactHit e = exactHit(towards, kGeneral);
        expectHit(towards, kGeneral, e.t, e.b1, e.b2, 1e-5, 1e-5, "the reversed ray", tally);
    }
    LESSON00_SUMMARY(tally, "rays");
}
