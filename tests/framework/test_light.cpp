// Tests of framework/light.h and Scene's light selection: area lights (triangles, spheres),
// point lights, the background; next-event estimation against Lambert's polygon formula.
#include <doctest/doctest.h>
#include <cmath>
#include <vector>
#include "light.h"
#include "rng.h"
#include "seed.h"
#include "scene.h"
#include "scene_loader.h"
#include "warps.h"

using namespace ps;

namespace {

// A scene built by hand: material 0 is a white diffuse, material 1 the black emitter material.
struct SceneBuilder {
    Scene s;
    SceneBuilder() {
        Material white, black;
        white.albedo = Color(0.8f);
        black.albedo = Color(0.0f);
        s.materials = {white, black};
        s.camera = Camera(Vec3(0, -20, 5), Vec3(0, 0, 0), Vec3(0, 0, 1), 40.0f, 8, 8);
    }
    int areaLight(const Color& Le) {
        Light l;
        l.kind = LightKind::Area;
        l.Le = Le;
        s.lights.push_back(l);
        return int(s.lights.size()) - 1;
    }
    uint32_t triangle(const Triangle& t, int light = -1) {
        const uint32_t prim = uint32_t(s.prims.size());
        s.prims.push_back({ShapeKind::Triangle, uint32_t(s.triangles.size()), light >= 0 ? 1 : 0, light});
        s.triangles.push_back(t);
        if (light >= 0) s.lights[light].prims.push_back(prim);
        return prim;
    }
    // Quad a b c d (counter-clockwise seen from the side its normal points to), as (a,b,c), (a,c,d).
    uint32_t quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, int light = -1) {
        const uint32_t first = triangle({a, b, c}, light);
        triangle({a, c, d}, light);
        return first;
    }
    uint32_t sphere(const Sphere& sp, int light = -1) {
        const uint32_t prim = uint32_t(s.prims.size());
        s.prims.push_back({ShapeKind::Sphere, uint32_t(s.spheres.size()), light >= 0 ? 1 : 0, light});
        s.spheres.push_back(sp);
        if (light >= 0) s.lights[light].prims.push_back(prim);
        return prim;
    }
    int pointLight(const Vec3& p, const Color& I) {
        Light l;
        l.kind = LightKind::Point;
        l.position = p;
        l.Le = I;
        s.lights.push_back(l);
        return int(s.lights.size()) - 1;
    }
    int background(const Color& Le) {
        Light l;
        l.kind = LightKind::Background;
        l.Le = Le;
        s.lights.push_back(l);
        return int(s.lights.size()) - 1;
    }
    Scene done() {
        s.finalize();
        return s;
    }
};

// Barycentric coordinates (b0, b1, b2) of p in triangle t, and its distance from t's plane.
glm::dvec3 barycentrics(const Triangle& t, const Vec3& p, double& planeDist) {
    const glm::dvec3 a(t.p0), e1 = glm::dvec3(t.p1) - a, e2 = glm::dvec3(t.p2) - a, q = glm::dvec3(p) - a;
    const glm::dvec3 n = glm::cross(e1, e2);
    planeDist = std::abs(glm::dot(q, n)) / glm::length(n);
    const double b1 = glm::dot(glm::cross(q, e2), n) / glm::dot(n, n),
                 b2 = glm::dot(glm::cross(e1, q), n) / glm::dot(n, n);
    return {1.0 - b1 - b2, b1, b2};
}

// Irradiance at x (normal nx) from a polygon of constant radiance Le, all of it above x's
// tangent plane. E = integral of Le cos(theta) d(omega) = Le times the projected solid angle;
// by Stokes' theorem the projected solid angle of a polygon is (1/2) sum over its edges of
// Theta_k (Gamma_k . nx), Theta_k = angle between the unit vectors to the edge's ends,
// Gamma_k = unit normal of the plane through x and the edge, v_k x v_k+1 normalised
// (Lambert 1760; Arvo 1995). The sign depends on the polygon's orientation: take |.|.
double lambertPolygonIrradiance(const std::vector<glm::dvec3>& poly, const glm::dvec3& x, const glm::dvec3& nx,
                                double Le) {
    double sum = 0.0;
    for (size_t k = 0; k < poly.size(); ++k) {
        const glm::dvec3 a = glm::normalize(poly[k] - x), b = glm::normalize(poly[(k + 1) % poly.size()] - x);
        const double theta = std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0));
        sum += theta * glm::dot(glm::normalize(glm::cross(a, b)), nx);
    }
    return 0.5 * Le * std::abs(sum);
}

// The same irradiance by brute-force quadrature over a rectangle's area (midpoint rule,
// n x n cells): E = integral of Le cos(theta_x) cos(theta_y) / d^2 dA.
double rectIrradianceByArea(const glm::dvec3& corner, const glm::dvec3& e1, const glm::dvec3& e2, const glm::dvec3& x,
                            const glm::dvec3& nx, double Le, int n) {
    const glm::dvec3 ny = glm::normalize(glm::cross(e1, e2));
    const double dA = glm::length(glm::cross(e1, e2)) / (double(n) * n);
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const glm::dvec3 y = corner + e1 * ((i + 0.5) / n) + e2 * ((j + 0.5) / n), d = y - x;
            const double d2 = glm::dot(d, d), dist = std::sqrt(d2);
            sum += Le * std::max(0.0, glm::dot(nx, d) / dist) * std::abs(glm::dot(ny, d) / dist) / d2 * dA;
        }
    return sum;
}

}  // namespace

TEST_CASE("light: Lambert's polygon formula (the reference of the NEE test) agrees with area quadrature") {
    // The reference itself is checked three ways: against brute-force area quadrature
    // (2000^2 cells, relative 1e-4), the small-light limit Le A cos cos / d^2, and the
    // infinite-plane limit pi Le.
    const glm::dvec3 x(0.0), n(0, 0, 1);
    struct Rect {
        glm::dvec3 c, e1, e2;
    };
    const Rect rects[] = {{{-1, -1, 1}, {2, 0, 0}, {0, 2, 0}},       // square on the axis
                          {{0.5, -1, 1}, {2, 0, 0}, {0, 3, 0}},      // off-axis rectangle
                          {{-1, -1, 2}, {2, 0, 0.5}, {0, 2, 0.3}}};  // tilted
    for (const Rect& r : rects) {
        const std::vector<glm::dvec3> poly = {r.c, r.c + r.e1, r.c + r.e1 + r.e2, r.c + r.e2};
        const double E = lambertPolygonIrradiance(poly, x, n, 1.0),
                     Eq = rectIrradianceByArea(r.c, r.e1, r.e2, x, n, 1.0, 2000);
        CHECK_MESSAGE(std::abs(E - Eq) < 1e-4 * Eq, "polygon formula " << E << " vs quadrature " << Eq);
    }
    const double tiny = 1e-3;  // square of side 2e-3 at height 1: E = A / 1
    CHECK(lambertPolygonIrradiance({{-tiny, -tiny, 1}, {tiny, -tiny, 1}, {tiny, tiny, 1}, {-tiny, tiny, 1}}, x, n,
                                   1.0) == doctest::Approx(4 * tiny * tiny).epsilon(1e-5));
    const double big = 1e4;
    CHECK(lambertPolygonIrradiance({{-big, -big, 1}, {big, -big, 1}, {big, big, 1}, {-big, big, 1}}, x, n, 1.0) ==
          doctest::Approx(M_PI).epsilon(1e-3));
}

TEST_CASE("light: area light sampling: uniform by area, pdf = 1/area, points on the light") {
    // Two triangles of areas 1 and 3 in different places form one light.
    SceneBuilder b;
    const int l = b.areaLight(Color(2.0f, 3.0f, 4.0f));
    const Triangle t0{Vec3(0, 0, 2), Vec3(0, 1, 2), Vec3(2, 0, 2)};     // area 1, normal -z
    const Triangle t1{Vec3(-3, 0, 0), Vec3(-3, 2, 0), Vec3(-3, 0, 3)};  // area 3, normal -x
    b.triangle(t0, l);
    b.triangle(t1, l);
    const Scene s = b.done();
    REQUIRE(s.lights[l].area == doctest::Approx(4.0f));
    CHECK(pdfLight(s, l).pdfA == doctest::Approx(0.25f));
    CHECK(pdfLight(s, l).pdfW == 0.0f);
    CHECK(s.caps.areaLights);
    CHECK_FALSE(s.lights[l].isDelta());

    // N samples: the fraction on t0 is 1/4, and within each triangle the fraction with
    // b0 > 1/2 (a corner sub-triangle of a quarter of the area) is 1/4. Binomial standard
    // errors; tolerance 5 of them (two-sided alpha ~ 6e-7 per check).
    const int N = 200000;
    Rng rng(testseed::seed(5));
    int onT0 = 0, corner[2] = {0, 0}, off = 0;
    for (int i = 0; i < N; ++i) {
        const LightSample ls = sampleLight(s, l, Vec3(1, 1, 1), rng.uniform2());
        double d0, d1;
        const glm::dvec3 c0 = barycentrics(t0, ls.p, d0), c1 = barycentrics(t1, ls.p, d1);
        const bool in0 = d0 < 1e-6 && glm::all(glm::greaterThanEqual(c0, glm::dvec3(-1e-6)));
        const bool in1 = d1 < 1e-6 && glm::all(glm::greaterThanEqual(c1, glm::dvec3(-1e-6)));
        if (in0 == in1) {
            if (++off <= 3)
                FAIL_CHECK("sample (" << ls.p.x << ", " << ls.p.y << ", " << ls.p.z << ") is on neither triangle");
            continue;
        }
        onT0 += in0;
        corner[in0 ? 0 : 1] += (in0 ? c0 : c1).x > 0.5;
        CHECK(ls.pdfA == doctest::Approx(0.25f));
        CHECK(ls.pdfW == 0.0f);
        CHECK(ls.n == (in0 ? t0 : t1).normal());
    }
    CHECK(off == 0);
    const double p0 = double(onT0) / N, se0 = std::sqrt(0.25 * 0.75 / N);
    CHECK_MESSAGE(std::abs(p0 - 0.25) < 5 * se0, "fraction on the area-1 triangle: expected 0.25, got " << p0);
    for (int k = 0; k < 2; ++k) {
        const int n = k == 0 ? onT0 : N - onT0;
        const double f = double(corner[k]) / n, se = std::sqrt(0.25 * 0.75 / n);
        CHECK_MESSAGE(std::abs(f - 0.25) < 5 * se,
                      "triangle " << k << ": fraction with b0 > 1/2 expected 0.25, got " << f);
    }
}

TEST_CASE("light: area lights are one-sided, sampleLight fills direction and distance") {
    SceneBuilder b;
    const int l = b.areaLight(Color(5.0f));
    b.quad(Vec3(-1, -1, 3), Vec3(-1, 1, 3), Vec3(1, 1, 3), Vec3(1, -1, 3), l);  // normal -z: emits downward
    const Scene s = b.done();
    REQUIRE(s.triangles[0].normal().z == doctest::Approx(-1.0f));
    Rng rng(testseed::seed(6));
    for (int i = 0; i < 1000; ++i) {
        const Vec2 u = rng.uniform2();
        const Vec3 below(0.3f, -0.2f, 0.0f), above(0.1f, 0.4f, 6.0f);
        const LightSample a = sampleLight(s, l, below, u), c = sampleLight(s, l, above, u);
        CHECK(a.Le == Color(5.0f));  // the emitting side
        CHECK(isBlack(c.Le));        // from the back: nothing
        CHECK(glm::length(a.wi - glm::normalize(a.p - below)) < 1e-6f);
        CHECK(a.dist == doctest::Approx(glm::length(a.p - below)));
        CHECK(std::abs(a.p.z - 3.0f) < 1e-6f);
    }
    CHECK(emittedRadiance(s.lights[l], Vec3(0, 0, -1), Vec3(0, 0.1f, -1)) == Color(5.0f));
    CHECK(isBlack(emittedRadiance(s.lights[l], Vec3(0, 0, -1), Vec3(0, 0.1f, 1))));
    CHECK(isBlack(emittedRadiance(s.lights[l], Vec3(0, 0, -1), Vec3(1, 0, 0))));  // exactly grazing
    CHECK(lightPower(s, l) == doctest::Approx(kPi * 4.0f * 5.0f));                // pi A Le, one side
}

TEST_CASE("light: sphere light samples lie on the sphere, uniformly, and emit outward") {
    SceneBuilder b;
    const int l = b.areaLight(Color(1.0f));
    const Sphere sph{Vec3(3, -2, 7), 0.75f};
    b.sphere(sph, l);
    const Scene s = b.done();
    CHECK(pdfLight(s, l).pdfA == doctest::Approx(1.0f / (4.0f * kPi * 0.75f * 0.75f)));
    const Vec3 ref(0, 0, 0);
    Rng rng(testseed::seed(7));
    const int N = 100000;
    glm::dvec3 meanN(0.0);
    int bad = 0;
    for (int i = 0; i < N; ++i) {
        const LightSample ls = sampleLight(s, l, ref, rng.uniform2());
        // On the sphere to float rounding of coordinates ~10: 1e-5 relative to |c| + r.
        const float r = glm::length(ls.p - sph.center);
        const bool ok = std::abs(r - sph.radius) < 1e-5f * 10.0f && glm::length(ls.n - (ls.p - sph.center) / r) < 1e-5f;
        // Emits outward: visible from ref exactly where the normal faces ref.
        const bool faces = glm::dot(ls.n, -ls.wi) > 0.0f;
        const bool leOk = faces ? ls.Le == Color(1.0f) : isBlack(ls.Le);
        if ((!ok || !leOk) && ++bad <= 3)
            FAIL_CHECK("sample at distance " << r << " from the centre, Le " << ls.Le.r << ", facing " << faces);
        meanN += glm::dvec3(ls.n);
    }
    CHECK(bad == 0);
    // Uniform on the sphere: each component of n has mean 0 and variance 1/3; 5 standard errors.
    meanN /= N;
    const double tol = 5.0 * std::sqrt(1.0 / 3.0 / N);
    CHECK_MESSAGE(glm::length(meanN) < tol * std::sqrt(3.0),
                  "mean normal of the samples: (" << meanN.x << ", " << meanN.y << ", " << meanN.z << ")");
}

namespace {
struct NeeCase {
    const char* name;
    float halfSide, height;
    Vec3 x;
};

// Next-event estimate of the irradiance at x (on a floor, normal +z) from a square light of
// half-side a at height h facing down: Welford mean and variance over N samples.
void neeIrradiance(const NeeCase& c, int N, double& mean, double& var) {
    SceneBuilder b;
    const float a = c.halfSide, h = c.height;
    const int l = b.areaLight(Color(1.5f));
    b.quad(Vec3(-a, -a, h), Vec3(-a, a, h), Vec3(a, a, h), Vec3(a, -a, h), l);                              // normal -z
    const uint32_t floor = b.quad(Vec3(-20, -20, 0), Vec3(20, -20, 0), Vec3(20, 20, 0), Vec3(-20, 20, 0));  // normal +z
    const Scene s = b.done();
    const SurfacePoint sp = s.surfacePoint(floor, c.x);
    Rng rng(testseed::seed(1000 + uint64_t(h * 10)));
    mean = 0.0;
    double m2 = 0.0;
    for (int i = 0; i < N; ++i) {
        float prob;
        const int li = s.selectLight(rng.uniform(), prob);
        const LightSample ls = sampleLight(s, li, sp.p, rng.uniform2());
        double v = 0.0;
        const float cosX = glm::dot(sp.n, ls.wi), cosY = glm::dot(ls.n, -ls.wi);
        if (!isBlack(ls.Le) && cosX > 0.0f && cosY > 0.0f) {
            SurfacePoint q;
            q.p = ls.p;
            q.n = ls.n;
            q.errScale = std::max(a, h);
            if (!s.occluded(s.spawnRayTo(sp, q))) v = ls.Le.g * cosX * cosY / (ls.dist * ls.dist * ls.pdfA * prob);
        }
        const double delta = v - mean;
        mean += delta / (i + 1);
        m2 += delta * (v - mean);
    }
    var = m2 / (N - 1);
}
}  // namespace

TEST_CASE("light: NEE irradiance under a square light equals Lambert's polygon formula (t-test)") {
    // t = |mean - E| / sqrt(var / N), two-sided, alpha = 1e-3 per case (N large: t ~ normal,
    // critical value 3.29). Power check: the standard error must be <= 1 % of E, or a noisy
    // (or wrongly weighted but high-variance) estimator could pass.
    const NeeCase cases[] = {
        {"large square (half-side 5) at height 1, point on the axis", 5.0f, 1.0f, Vec3(0, 0, 0)},
        {"square of half-side 1 at height 1, point on the axis", 1.0f, 1.0f, Vec3(0, 0, 0)},
        {"square of half-side 1 at height 0.5, point off to the side", 1.0f, 0.5f, Vec3(1.5f, 0.4f, 0)}};
    const int N = 300000;
    for (const NeeCase& c : cases) {
        const double a = c.halfSide, h = c.height;
        const std::vector<glm::dvec3> poly = {{-a, -a, h}, {a, -a, h}, {a, a, h}, {-a, a, h}};
        const double E = lambertPolygonIrradiance(poly, glm::dvec3(c.x), glm::dvec3(0, 0, 1), 1.5);
        double mean, var;
        neeIrradiance(c, N, mean, var);
        const double se = std::sqrt(var / N), t = std::abs(mean - E) / se;
        INFO(c.name << ": expected E = " << E << ", got " << mean << " +- " << se << " (t = " << t << ")");
        CHECK(t < 3.29);
        CHECK(se <= 0.01 * E);
    }
}

TEST_CASE("light: selection by power picks lights with powers 1:3 with probabilities 1/4 and 3/4") {
    for (int kind = 0; kind < 2; ++kind) {
        SceneBuilder b;
        if (kind == 0) {  // point lights of intensity 1 and 3: power 4 pi I
            b.pointLight(Vec3(0, 0, 1), Color(1.0f));
            b.pointLight(Vec3(0, 0, 2), Color(3.0f));
        } else {  // area lights of equal area and radiance 1 and 3: power pi A Le
            const int l0 = b.areaLight(Color(1.0f)), l1 = b.areaLight(Color(3.0f));
            b.quad(Vec3(0, 0, 1), Vec3(0, 1, 1), Vec3(1, 1, 1), Vec3(1, 0, 1), l0);
            b.quad(Vec3(5, 0, 1), Vec3(5, 1, 1), Vec3(6, 1, 1), Vec3(6, 0, 1), l1);
        }
        const Scene s = b.done();
        INFO((kind == 0 ? "point lights" : "area lights"));
        CHECK(s.lightSelectionProb(0) == doctest::Approx(0.25f).epsilon(1e-6));
        CHECK(s.lightSelectionProb(1) == doctest::Approx(0.75f).epsilon(1e-6));
        // selectLight over a uniform grid of u: light 0 exactly for the first quarter (+-1 cell).
        const int M = 10000;
        int first = 0;
        for (int i = 0; i < M; ++i) {
            float prob;
            const int li = s.selectLight((i + 0.5f) / M, prob);
            REQUIRE((li == 0 || li == 1));
            CHECK(prob == s.lightSelectionProb(li));
            first += li == 0;
        }
        CHECK_MESSAGE(std::abs(first - M / 4) <= 1,
                      "light 0 chosen for " << first << " of " << M << " grid points, expected " << M / 4);
    }
    // No lights: selectLight says so.
    SceneBuilder empty;
    empty.quad(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0));
    const Scene s = empty.done();
    float prob = 1.0f;
    CHECK(s.selectLight(0.5f, prob) == -1);
    CHECK(prob == 0.0f);
    CHECK_FALSE(s.caps.hasLights());
}

TEST_CASE("light: point lights are delta lights with pdf 1") {
    SceneBuilder b;
    const int l = b.pointLight(Vec3(1, 2, 3), Color(7.0f));
    const Scene s = b.done();
    CHECK(s.lights[l].isDelta());
    CHECK(s.caps.pointLights);
    const LightSample ls = sampleLight(s, l, Vec3(1, 2, 0), Vec2(0.3f, 0.9f));
    CHECK(ls.p == Vec3(1, 2, 3));
    CHECK(ls.pdfA == 1.0f);
    CHECK(ls.pdfW == 0.0f);
    CHECK(ls.Le == Color(7.0f));
    CHECK(ls.dist == doctest::Approx(3.0f));
    CHECK(glm::length(ls.wi - Vec3(0, 0, 1)) < 1e-6f);
    const EmissionSample e = sampleEmission(s, l, Vec2(0.2f, 0.4f), Vec2(0.7f, 0.1f));
    CHECK(e.p == Vec3(1, 2, 3));
    CHECK(e.pdfA == 1.0f);
    CHECK(e.pdfW == doctest::Approx(1.0f / (4.0f * kPi)));
    CHECK(std::abs(glm::length(e.dir) - 1.0f) < 1e-6f);
    const EmissionPdf q = pdfEmission(s, l, e.n, e.dir);
    CHECK(q.pdfA == e.pdfA);
    CHECK(q.pdfW == e.pdfW);
    CHECK(lightPower(s, l) == doctest::Approx(4.0f * kPi * 7.0f));
}

TEST_CASE(
    "light: a point light in a corner of three walls: rays leave each wall's plane to their own side, and "
    "points in those planes do not see it") {
    // Issue 31: a point light where three surfaces meet was offset along their mean normal only;
    // 3/8 of the directions (towards the mean normal but out of the walls' octant) then started
    // inside the octant, hit a wall at t ~ 0 next to the light and scattered light there that no
    // shadow ray sees: lt and bpt rendered the Cornell box 1.5 to 2 times too bright. The walls
    // here are the planes x = 0, y = 0, z = 0, so "its own side" is the sign of each coordinate.
    const Scene scene = parseScene(
        "camera eye 2 1.5 3  target 0.5 0.5 0.5  fov 60  resolution 4 4\n"
        "material w diffuse albedo 0.5 0.5 0.5\n"
        "quad 0 0 0  0 0 1  1 0 1  1 0 0  material w\n"  // y = 0
        "quad 0 0 0  0 1 0  0 1 1  0 0 1  material w\n"  // x = 0
        "quad 0 0 0  1 0 0  1 1 0  0 1 0  material w\n"  // z = 0
        "sphere center 0.6 0.3 0.6  radius 0.1  material w\n"
        "pointlight position 0 0 0  intensity 1 1 1\n",
        "corner.scene");
    REQUIRE(scene.lights[0].surfacePlanes.size() == 3);
    SurfacePoint light;
    light.p = Vec3(0.0f);
    light.light = 0;
    Rng rng(testseed::seed(31));
    int wrongSide = 0, nearHits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 w = sampleUniformSphere(rng.uniform2());
        Ray ray = scene.spawnRay(light, w);
        for (int a = 0; a < 3; ++a)
            if (w[a] != 0.0f && (ray.o[a] > 0.0f) != (w[a] > 0.0f)) ++wrongSide;
        SurfacePoint hit;
        if (scene.intersect(ray, hit) && ray.tMax < 1e-3f) ++nearHits;
    }
    CHECK_MESSAGE(wrongSide == 0, wrongSide << " ray origins on the other side of a wall's plane than their direction");
    CHECK_MESSAGE(nearHits == 0, nearHits << " rays from the light hit a wall it lies on, next to it");
    // A point of the floor (in a plane of the light) does not see it; a point of the sphere does.
    Ray down(Vec3(0.3f, 1.0f, 0.4f), Vec3(0, -1, 0));
    SurfacePoint floor;
    REQUIRE(scene.intersect(down, floor));
    CHECK(scene.occluded(scene.spawnRayTo(floor, Vec3(0.0f))));
    Ray toSphere(Vec3(0.2f, 0.1f, 0.2f), glm::normalize(Vec3(0.4f, 0.2f, 0.4f)));  // its side facing the light
    SurfacePoint onSphere;
    REQUIRE(scene.intersect(toSphere, onSphere));
    CHECK(!scene.occluded(scene.spawnRayTo(onSphere, Vec3(0.0f))));
    CHECK(!scene.occluded(scene.spawnRayTo(light, onSphere)));
}

TEST_CASE("light: background sampling is uniform over the sphere with pdf 1/(4 pi)") {
    SceneBuilder b;
    b.quad(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0));
    const int l = b.background(Color(0.5f));
    const Scene s = b.done();
    CHECK(s.lights[l].isInfinite());
    CHECK_FALSE(s.lights[l].isDelta());
    CHECK(s.caps.backgroundLight);
    CHECK(s.background == l);
    CHECK(s.backgroundRadiance() == Color(0.5f));
    CHECK(pdfLight(s, l).pdfW == doctest::Approx(1.0f / (4.0f * kPi)));
    CHECK(pdfLight(s, l).pdfA == 0.0f);
    // Mean direction 0 (each component: variance 1/3), 5 standard errors.
    Rng rng(testseed::seed(8));
    const int N = 100000;
    glm::dvec3 mean(0.0);
    for (int i = 0; i < N; ++i) {
        const LightSample ls = sampleLight(s, l, Vec3(0.2f, 0.1f, 0.5f), rng.uniform2());
        CHECK(ls.pdfW == doctest::Approx(1.0f / (4.0f * kPi)));
        CHECK(ls.pdfA == 0.0f);
        CHECK(std::abs(glm::length(ls.wi) - 1.0f) < 1e-5f);
        CHECK(ls.dist == kInf);
        CHECK(ls.Le == Color(0.5f));
        mean += glm::dvec3(ls.wi);
    }
    mean /= N;
    const double tol = 5.0 * std::sqrt(1.0 / 3.0 / N);
    CHECK_MESSAGE((std::abs(mean.x) < tol && std::abs(mean.y) < tol && std::abs(mean.z) < tol),
                  "mean direction (" << mean.x << ", " << mean.y << ", " << mean.z << "), expected 0 +- " << tol);
    // Emission: a direction, and the origin on the disk of radius R outside the bounding sphere.
    const EmissionSample e = sampleEmission(s, l, Vec2(0.3f, 0.6f), Vec2(0.2f, 0.8f));
    CHECK(e.pdfA == doctest::Approx(1.0f / (kPi * s.radius * s.radius)));
    CHECK(e.pdfW == doctest::Approx(1.0f / (4.0f * kPi)));
    CHECK(glm::dot(e.p - s.center, e.dir) == doctest::Approx(-s.radius).epsilon(1e-4));
    const EmissionPdf q = pdfEmission(s, l, e.n, e.dir);
    CHECK(q.pdfA == e.pdfA);
    CHECK(q.pdfW == e.pdfW);
}

TEST_CASE("light: area light emission: cosine directions on the normal side, pdfW = cos/pi, pdfA = 1/area") {
    SceneBuilder b;
    const int l = b.areaLight(Color(2.0f));
    b.quad(Vec3(0, 0, 1), Vec3(0, 2, 1.5f), Vec3(3, 2, 1.5f), Vec3(3, 0, 1), l);  // tilted, normal down-ish
    const Scene s = b.done();
    const Vec3 n = s.triangles[0].normal();
    // Under pdf cos/pi: E[cos] = 2/3 and E[cos^2] = 1/2, so Var[cos] = 1/18. 5 standard errors.
    Rng rng(testseed::seed(9));
    const int N = 100000;
    double sumCos = 0.0;
    int bad = 0;
    for (int i = 0; i < N; ++i) {
        const Vec2 uPos = rng.uniform2();
        const Vec2 uDir = rng.uniform2();
        const EmissionSample e = sampleEmission(s, l, uPos, uDir);
        const float c = glm::dot(e.dir, n);
        double d;
        const bool onLight = glm::all(glm::greaterThanEqual(barycentrics(s.triangles[0], e.p, d), glm::dvec3(-1e-6))) ||
                             glm::all(glm::greaterThanEqual(barycentrics(s.triangles[1], e.p, d), glm::dvec3(-1e-6)));
        const EmissionPdf q = pdfEmission(s, l, e.n, e.dir);  // the matching pdf function
        const bool ok = c >= 0.0f && std::abs(e.pdfW - c / kPi) <= 1e-5f &&
                        e.pdfA == doctest::Approx(1.0f / s.lights[l].area) && std::abs(q.pdfW - e.pdfW) <= 1e-5f &&
                        q.pdfA == e.pdfA && e.n == n && e.Le == Color(2.0f) &&
                        std::abs(glm::dot(e.p - Vec3(0, 0, 1), n)) < 1e-5f && onLight;
        if (!ok && ++bad <= 3)
            FAIL_CHECK("emission sample: cos " << c << ", pdfW " << e.pdfW << " (expected " << c / kPi << "), pdfA "
                                               << e.pdfA << " (expected " << 1.0f / s.lights[l].area << ")");
        sumCos += c;
    }
    CHECK(bad == 0);
    const double meanCos = sumCos / N, tol = 5.0 * std::sqrt(1.0 / 18.0 / N);
    CHECK_MESSAGE(std::abs(meanCos - 2.0 / 3.0) < tol,
                  "mean cos of emitted directions: expected 2/3 +- " << tol << ", got " << meanCos);
}
