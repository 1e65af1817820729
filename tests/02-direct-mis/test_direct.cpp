// Lesson 2, graded: light sampling and BSDF sampling (lessons/02-direct-mis/direct.h; Eq.
// 2.3-2.5), and every estimator against Lambert's closed form for the irradiance from polygonal
// lights (Eq. 2.13): t-tests at level alpha() (lesson02.h) with a power check.
#include <cmath>
#include "lesson02.h"
#include "seed.h"

using namespace lesson02;

namespace {

// A diffuse floor (y = 0, albedo 0.6 0.5 0.4) under two polygonal lights of different power:
// a tilted parallelogram and a triangle, both facing down. Seen from the floor points used
// below, both lie wholly above the horizon, face the point and do not hide each other.
const char* kPolygonScene = R"(
camera eye 0 6 6  target 0 0 0  fov 40  resolution 1 1
material floor diffuse albedo 0.6 0.5 0.4
quad -5 0 -5  -5 0 5  5 0 5  5 0 -5  material floor
quad -1 2 -0.5  1 2.5 -0.5  1.2 2.5 0.8  -0.8 2 0.8  emission 4 2 1
triangle 1.5 1.5 1  2.5 1.8 0.5  2 1.2 2  emission 1 2 6
)";
const Color kAlbedo(0.6f, 0.5f, 0.4f);

struct Polygon {
    std::vector<glm::dvec3> v;
    glm::dvec3 Le;
};
const std::vector<Polygon> kLights = {
    {{{-1, 2, -0.5}, {1, 2.5, -0.5}, {1.2, 2.5, 0.8}, {-0.8, 2, 0.8}}, {4, 2, 1}},
    {{{1.5, 1.5, 1}, {2.5, 1.8, 0.5}, {2, 1.2, 2}}, {1, 2, 6}},
};

// Lambert's formula (Eq. 2.13): the irradiance at x (normal n) from a polygon of radiance 1
// wholly above x's horizon, facing x: E = 1/2 |sum_k Theta_k (Gamma_k . n)|, Theta_k the angle
// edge k subtends at x, Gamma_k the unit normal of the plane through x and that edge.
double polygonIrradiance(const std::vector<glm::dvec3>& v, const glm::dvec3& x, const glm::dvec3& n) {
    double s = 0.0;
    for (size_t k = 0; k < v.size(); ++k) {
        const glm::dvec3 a = glm::normalize(v[k] - x), b = glm::normalize(v[(k + 1) % v.size()] - x);
        const double theta = std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0));
        s += theta * glm::dot(glm::normalize(glm::cross(a, b)), n);
    }
    return 0.5 * std::abs(s);
}

// Radiance leaving the floor point x upwards, summed over R, G and B: (albedo / pi) E.
double expectedRadianceSum(const glm::dvec3& x) {
    glm::dvec3 L(0.0);
    for (const Polygon& p : kLights) L += p.Le * polygonIrradiance(p.v, x, {0, 1, 0});
    return glm::dot(glm::dvec3(kAlbedo) / 3.14159265358979323846, L);
}

// Whether the ray from o in direction d passes within `eps` (relative to the edge's length) of
// one of the lights: a light sample on a polygon's edge that the test's own ray, rounded
// differently, just misses.
bool grazesLight(const glm::dvec3& o, const glm::dvec3& d, double eps) {
    for (const Polygon& p : kLights) {
        const glm::dvec3 n = glm::normalize(glm::cross(p.v[1] - p.v[0], p.v[2] - p.v[0]));
        const double dn = glm::dot(d, n);
        if (dn == 0.0) continue;
        const double t = glm::dot(p.v[0] - o, n) / dn;
        if (t <= 0.0) continue;
        const glm::dvec3 h = o + t * d;
        bool inside = true;
        for (size_t k = 0; k < p.v.size(); ++k) {
            const glm::dvec3 e = p.v[(k + 1) % p.v.size()] - p.v[k];
            inside = inside && glm::dot(glm::cross(e, h - p.v[k]), n) >= -eps * glm::dot(e, e);
        }
        if (inside) return true;
    }
    return false;
}

// The ray that sees the floor point x (from 0.5 above it, below both lights).
ps::Ray rayTo(const Vec3& x) {
    const Vec3 o = x + Vec3(0.1f, 0.5f, -0.15f);
    return ps::Ray(o, glm::normalize(x - o));
}

// n samples of an integrator's Li along the ray to x, summed over R, G, B: mean and variance,
// and the count of non-finite samples.
struct Samples {
    ps::stats::Welford w;
    int bad = 0;
};
Samples sampleLi(const ps::Scene& scene, const std::string& algo, const Vec3& x, int n, uint64_t seed) {
    const std::unique_ptr<ps::Integrator> integrator = ps::makeIntegrator(algo);
    const auto* pixel = dynamic_cast<const ps::PixelIntegrator*>(integrator.get());
    REQUIRE(pixel != nullptr);
    Samples s;
    const ps::Ray ray = rayTo(x);
    for (int i = 0; i < n; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(seed), 0, uint32_t(i));
        const Color c = pixel->Li(scene, ray, rng);
        if (!ps::isFinite(c)) {
            ++s.bad;
            continue;
        }
        s.w.add(sum(c));
    }
    return s;
}

// The t-test of one estimator at the two floor points: standard error at most 0.5 % of the
// expected value (power check).
void checkLambert(const std::string& algo, int n, uint64_t seed) {
    const ps::Scene scene = ps::parseScene(kPolygonScene, "polygon-lights (test_direct.cpp)");
    for (const Vec3& x : {Vec3(0.2f, 0.0f, 0.1f), Vec3(1.5f, 0.0f, 2.5f)}) {
        const double expected = expectedRadianceSum(glm::dvec3(x));
        const Samples s = sampleLi(scene, algo, x, n, seed++);
        CHECK_MESSAGE(s.bad == 0,
                      algo << " at floor point " << str(x) << ": expected 0 NaN or Inf samples, got " << s.bad);
        const ps::stats::TTestResult t = ps::stats::tTest(s.w, expected, alpha(), 0.005);
        CHECK_MESSAGE(t.passed, algo << ", radiance (R + G + B) leaving the floor point " << str(x)
                                     << " under two polygonal lights, " << n << " samples: expected (albedo / pi) E = "
                                     << expected << " by Lambert's formula, got " << t.mean << " +- " << t.stdError
                                     << "\n  " << t.report);
    }
}

}  // namespace

TEST_CASE("direct: area pdfs become solid-angle pdfs (Eq. 2.3) [1 pt]") {
    struct Case {
        float pdfA, dist, cosAtLight, expected;
    };
    for (const Case& c :
         {Case{2.0f, 3.0f, 0.5f, 36.0f}, Case{0.25f, 10.0f, 1.0f, 25.0f}, Case{1e-4f, 1e3f, 0.1f, 1000.0f},
          Case{1.0f, 1.0f, 0.0f, 0.0f}, Case{1.0f, 2.0f, -0.5f, 0.0f}}) {
        const float got = ps::pdfAToSolidAngle(c.pdfA, c.dist, c.cosAtLight);
        CHECK_MESSAGE(std::abs(got - c.expected) <= 1e-5f * c.expected,
                      "pdfAToSolidAngle(pdfA " << c.pdfA << ", dist " << c.dist << ", cos " << c.cosAtLight
                                               << "): expected " << c.expected << ", got " << got);
    }
    // pdfLightDirection: selection probability (by power) times the converted pdf.
    const ps::Scene scene = ps::parseScene(kPolygonScene, "polygon-lights (test_direct.cpp)");
    const Vec3 ref(0.2f, 0.0f, 0.1f);
    for (int l = 0; l < 2; ++l) {
        const Vec3 p = l == 0 ? Vec3(0.1f, 2.25f, 0.15f) : Vec3(2.0f, 1.5f, 1.1666667f);  // inside each light
        const Vec3 n = ps::Triangle{Vec3(kLights[l].v[0]), Vec3(kLights[l].v[1]), Vec3(kLights[l].v[2])}.normal();
        const double d = glm::length(glm::dvec3(ref - p)), cosL = glm::dot(glm::dvec3(n), glm::dvec3(ref - p)) / d;
        const double expected = scene.lightSelectionProb(l) / scene.lights[l].area * d * d / cosL;
        const float got = ps::pdfLightDirection(scene, l, ref, p, n);
        CHECK_MESSAGE(std::abs(got - expected) <= 1e-4 * expected,
                      "pdfLightDirection(light " << l << ", from " << str(ref) << " to " << str(p) << "): expected "
                                                 << "P(light) / area * d^2 / cos = " << scene.lightSelectionProb(l)
                                                 << " / " << scene.lights[l].area << " * " << d * d << " / " << cosL
                                                 << " = " << expected << ", got " << got);
    }
}

TEST_CASE("direct: light and BSDF samples carry f Le cos / pdf and the pdfs of both techniques [2 pts]") {
    // From the floor point under the two polygonal lights, 2000 light samples and 2000 BSDF
    // samples. Every sample that reaches a light is checked against the test's own computation
    // for its direction wi: trace wi to the light point y, then
    //   pdfLight = P(light) / area * d^2 / cos_y,  pdfBSDF = cos_x / pi,
    //   value    = (albedo / pi) Le cos_x / pdf of the technique that took it.
    const ps::Scene scene = ps::parseScene(kPolygonScene, "polygon-lights (test_direct.cpp)");
    const ps::Ray camera = rayTo(Vec3(0.2f, 0.0f, 0.1f));
    ps::Ray r = camera;
    ps::SurfacePoint sp;
    REQUIRE(scene.intersect(r, sp));
    const Vec3 wo = -camera.d;
    ps::Rng rng(ps::testseed::seed(25));
    int failures = 0, checked[2] = {0, 0}, grazing = 0;
    for (int technique = 0; technique < 2; ++technique)
        for (int i = 0; i < 2000; ++i) {
            const float uLight = technique == 0 ? rng.uniform() : 0.0f;
            const Vec2 u = rng.uniform2();
            const float uLobe = technique == 0 ? 0.0f : rng.uniform();
            const ps::DirectSample d = technique == 0 ? ps::sampleDirectLight(scene, sp, wo, uLight, u)
                                                      : ps::sampleDirectBSDF(scene, sp, wo, u, uLobe);
            ps::Ray toLight = scene.spawnRay(sp, d.wi);
            ps::SurfacePoint y;
            const bool hitsLight = glm::length(d.wi) > 0.5f && scene.intersect(toLight, y) && y.light >= 0;
            if (!hitsLight) {
                // A sample on a light's very edge (PATHSPACE_TEST_SEED 2 drew one): the test's
                // ray misses by rounding; within 1e-5 of the edge it proves nothing either way.
                if (technique == 0 && grazesLight(glm::dvec3(toLight.o), glm::dvec3(d.wi), 1e-5)) {
                    ++grazing;
                    continue;
                }
                if (technique == 0 && sum(d.value) != 0.0 && ++failures <= 3)
                    FAIL_CHECK("light sample from " << str(sp.p) << ": direction " << str(d.wi)
                                                    << " does not lead to a light, but the value is " << str(d.value));
                continue;
            }
            ++checked[technique];
            const double dist = glm::length(glm::dvec3(y.p - sp.p));
            const double cosY = -glm::dot(glm::dvec3(y.n), glm::dvec3(d.wi)), cosX = std::abs(d.wi.y);
            const double pdfLight = scene.lightSelectionProb(y.light) / scene.lights[y.light].area * dist * dist / cosY;
            const double pdfBSDF = cosX / 3.14159265358979323846;
            const glm::dvec3 value = glm::dvec3(kAlbedo) / 3.14159265358979323846 *
                                     glm::dvec3(scene.lights[y.light].Le) * cosX /
                                     (technique == 0 ? pdfLight : pdfBSDF);
            auto close = [](double a, double b) { return std::abs(a - b) <= 2e-3 * std::abs(b) + 1e-12; };
            const bool ok = close(d.pdfLight, pdfLight) && close(d.pdfBSDF, pdfBSDF) && close(d.value.r, value.r) &&
                            close(d.value.g, value.g) && close(d.value.b, value.b) && !d.delta;
            if (!ok && ++failures <= 3)
                FAIL_CHECK((technique == 0 ? "light" : "BSDF")
                           << " sample from " << str(sp.p) << " towards " << str(d.wi) << " (light " << y.light
                           << " at " << str(y.p) << "):\n  expected pdfLight " << pdfLight << ", pdfBSDF " << pdfBSDF
                           << ", value (" << value.r << ", " << value.g << ", " << value.b
                           << "), delta 0\n  got      pdfLight " << d.pdfLight << ", pdfBSDF " << d.pdfBSDF
                           << ", value " << str(d.value) << ", delta " << d.delta);
        }
    CHECK_MESSAGE((checked[0] > 1000 && checked[1] > 50), "expected most light samples (got "
                                                              << checked[0] << " of 2000) and some BSDF samples (got "
                                                              << checked[1] << " of 2000) to reach a light");
    CHECK_MESSAGE(failures == 0,
                  "expected every sample that reaches a light to be right, got " << failures << " wrong");
    CHECK_MESSAGE(grazing <= 5, grazing << " light samples of 2000 graze a light's edge (expected a rare few)");
}

TEST_CASE("direct: light sampling gives Lambert's irradiance from polygonal lights (t-test) [2 pts]") {
    checkLambert("direct-light", 50000, 100);
}

TEST_CASE("direct: BSDF sampling gives Lambert's irradiance from polygonal lights (t-test) [1 pt]") {
    checkLambert("direct-bsdf", 1000000, 110);
}

TEST_CASE("direct: multi-sample MIS gives Lambert's irradiance with each heuristic (t-test) [2 pts]") {
    checkLambert("direct-balance", 50000, 120);
    checkLambert("direct-power", 50000, 130);
    checkLambert("direct-max", 50000, 140);
}

TEST_CASE("direct: one-sample MIS gives Lambert's irradiance from polygonal lights (t-test) [1 pt]") {
    checkLambert("direct-onesample", 120000, 150);
}

TEST_CASE(
    "direct: multi-sample and one-sample MIS weight each sample by the heuristic they are given (Eq. 2.6, 2.11) [1 pt]") {
    // The two combined estimators, called with the same random numbers as your own light and
    // BSDF samples, must return exactly what Eq. 2.6 and 2.11 make of those samples with YOUR
    // misWeight and the heuristic passed in (the unbiasedness tests above cannot tell the
    // heuristics apart: all three are unbiased). Surface points: the plates of
    // data/plates-moderate.scene, where both techniques often reach the same light.
    const ps::Scene scene = ps::loadScene(sourcePath("tests/02-direct-mis/data/plates-moderate.scene"));
    const float c = ps::kOneSampleLightProbability;
    ps::Rng rng(ps::testseed::seed(26));
    const ps::Heuristic heuristics[] = {ps::Heuristic::Balance, ps::Heuristic::Power, ps::Heuristic::Maximum};
    const char* names[] = {"balance", "power", "maximum"};
    int failures = 0, both = 0;
    for (int y = 1; y < 32; y += 3)
        for (int x = 1; x < 32; x += 3) {
            ps::Ray ray = scene.camera.generateRay(Vec2(x + 0.5f, y + 0.5f));
            const Vec3 wo = -ray.d;
            ps::SurfacePoint sp;
            if (!scene.intersect(ray, sp) || sp.light >= 0) continue;
            for (int i = 0; i < 40; ++i) {
                ps::DirectRandom u;
                u.uLight = rng.uniform();
                u.uPoint = rng.uniform2();
                u.uBSDF = rng.uniform2();
                u.uLobe = rng.uniform();
                u.uChoice = rng.uniform();
                const ps::DirectSample a = ps::sampleDirectLight(scene, sp, wo, u.uLight, u.uPoint);
                const ps::DirectSample b = ps::sampleDirectBSDF(scene, sp, wo, u.uBSDF, u.uLobe);
                if (sum(a.value) > 0.0 && sum(b.value) > 0.0) ++both;
                for (int h = 0; h < 3; ++h) {
                    const ps::Heuristic H = heuristics[h];
                    const Color multi = ps::misWeight(H, 1.0f, a.pdfLight, 1.0f, a.pdfBSDF) * a.value +
                                        ps::misWeight(H, 1.0f, b.pdfBSDF, 1.0f, b.pdfLight) * b.value;
                    const Color one =
                        u.uChoice < c ? a.value * (ps::misWeight(H, c, a.pdfLight, 1.0f - c, a.pdfBSDF) / c)
                                      : b.value * (ps::misWeight(H, 1.0f - c, b.pdfBSDF, c, b.pdfLight) / (1.0f - c));
                    const Color gotMulti = ps::directMultiSample(scene, sp, wo, H, u);
                    const Color gotOne = ps::directOneSample(scene, sp, wo, H, u);
                    auto close = [](const Color& p, const Color& q) {
                        for (int k = 0; k < 3; ++k)
                            if (!(std::abs(p[k] - q[k]) <= 1e-4f * std::max(std::abs(q[k]), 1e-3f))) return false;
                        return true;
                    };
                    if (!close(gotMulti, multi) && ++failures <= 3)
                        FAIL_CHECK("directMultiSample(" << names[h] << ") at " << str(sp.p) << ": expected w_light "
                                                        << "* light sample + w_bsdf * BSDF sample = " << str(multi)
                                                        << " (light sample " << str(a.value) << ", pdfs " << a.pdfLight
                                                        << " / " << a.pdfBSDF << "; BSDF sample " << str(b.value)
                                                        << ", pdfs " << b.pdfBSDF << " / " << b.pdfLight << "), got "
                                                        << str(gotMulti));
                    if (!close(gotOne, one) && ++failures <= 3)
                        FAIL_CHECK("directOneSample("
                                   << names[h] << ") at " << str(sp.p) << " with uChoice " << u.uChoice << ": expected "
                                   << (u.uChoice < c ? "w_light * light sample / c" : "w_bsdf * BSDF sample / (1 - c)")
                                   << " = " << str(one) << " (weights with n = c, 1 - c), got " << str(gotOne));
                }
            }
        }
    CHECK_MESSAGE(both >= 100,
                  "expected at least 100 cases where both the light and the BSDF sample reach a light, got " << both);
    CHECK_MESSAGE(failures == 0, "expected every combined estimate to be the weighted sum of its samples, got "
                                     << failures << " wrong");
}
