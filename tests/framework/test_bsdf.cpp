// Tests of framework/bsdf.h: Lambertian, normalized Phong, mirror and smooth dielectric.
#include <doctest/doctest.h>
#include <cmath>
#include <functional>
#include <vector>
#include "bsdf.h"
#include "rng.h"
#include "seed.h"

using namespace ps;

namespace {

const float kExponents[] = {0.0f, 1.0f, 10.0f, 100.0f, 1e4f, 1e6f};
// cos(theta_o) of the outgoing directions: normal, oblique, grazing, and the other side.
const float kCosO[] = {1.0f, 0.5f, 0.1f, 1e-3f, -0.5f, -1e-3f};
const Vec3 kNormal = glm::normalize(Vec3(1.0f, 2.0f, 3.0f));  // not axis-aligned: exercises Frame

Material diffuse(float albedo = 0.7f) {
    Material m;
    m.kind = BSDFKind::Diffuse;
    m.albedo = Color(albedo);
    return m;
}
Material phong(float exponent, float albedo = 0.7f) {
    Material m;
    m.kind = BSDFKind::Phong;
    m.exponent = exponent;
    m.albedo = Color(albedo);
    return m;
}
Material mirror() {
    Material m;
    m.kind = BSDFKind::Mirror;
    m.albedo = Color(0.9f, 0.8f, 0.7f);
    return m;
}
Material glass(float ior) {
    Material m;
    m.kind = BSDFKind::Dielectric;
    m.ior = ior;
    return m;
}

// Unit direction at angle acos(c) from axis, at azimuth phi (in double, rounded once to float).
Vec3 dirAround(const Vec3& axis, double c, double phi) {
    const Frame f(axis);
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    const glm::dvec3 d =
        glm::dvec3(f.s) * (s * std::cos(phi)) + glm::dvec3(f.t) * (s * std::sin(phi)) + glm::dvec3(f.n) * c;
    return Vec3(glm::normalize(d));
}
Vec3 sideNormal(const Vec3& n, const Vec3& wo) { return glm::dot(n, wo) < 0.0f ? -n : n; }
Vec3 outgoing(float cosO) { return dirAround(kNormal, cosO, 0.7); }

// The integral of g over the unit sphere on a midpoint grid: the hemisphere about `axis`
// through the Phong-lobe warp of exponent k on N x N cells (cos(alpha) = (1 - x)^(1/(k+1)),
// density q = (k+1)/(2 pi) cos^k(alpha), so the estimate is mean(g / q)), plus the opposite
// hemisphere through the uniform warp (density 1/(2 pi)) on N/4 x N/4 cells. The warp puts
// the grid where a lobe of exponent ~k lives, so exponents up to 1e6 are integrated accurately.
double sphereIntegral(const std::function<double(const Vec3&)>& g, const Vec3& axis, double k, int N) {
    const Frame f(axis);
    const glm::dvec3 fs(f.s), ft(f.t), fn(f.n);
    auto dir = [&](double c, double phi) {
        const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
        return Vec3(glm::normalize(fs * (s * std::cos(phi)) + ft * (s * std::sin(phi)) + fn * c));
    };
    double lobe = 0.0, rest = 0.0;
    for (int i = 0; i < N; ++i) {
        const double c = std::pow(1.0 - (i + 0.5) / N, 1.0 / (k + 1.0));
        for (int j = 0; j < N; ++j) {
            const Vec3 w = dir(c, 2.0 * M_PI * (j + 0.5) / N);
            const double ca = glm::dot(glm::dvec3(w), glm::dvec3(axis));  // of the float direction
            const double q = (k + 1.0) / (2.0 * M_PI) * std::pow(std::max(ca, 0.0), k);
            if (q > 0.0) lobe += g(w) / q;
        }
    }
    const int M = N / 4;
    for (int i = 0; i < M; ++i)
        for (int j = 0; j < M; ++j) rest += g(dir(-(i + 0.5) / M, 2.0 * M_PI * (j + 0.5) / M)) * 2.0 * M_PI;
    return lobe / (double(N) * N) + rest / (double(M) * M);
}

// Probability that a direction drawn from the Phong lobe of exponent k about the mirror
// direction r lies above the surface, where r makes the angle beta with the surface
// (sin(beta) = r . ns = |cos(theta_o)|). A direction at angle alpha from r, azimuth phi
// (phi = 0 towards ns) has ns-component cos(alpha) sin(beta) + sin(alpha) cos(beta) cos(phi),
// positive iff cos(phi) > -tan(beta) / tan(alpha): a fraction acos(clamp(.)) / pi of the
// circle. Integrated over the lobe with x = 1 - cos^(k+1)(alpha) uniform (midpoint rule,
// 1e5 points; the integrand is smooth but for a square-root kink: error ~ 1e5^-1.5 ~ 3e-8).
// Exponent 0 is Lambertian (sampled over the whole hemisphere): probability 1.
double aboveProbability(double k, double cosThetaO) {
    if (k == 0.0) return 1.0;
    const double beta = std::asin(std::min(1.0, std::abs(cosThetaO)));
    const int M = 100000;
    double sum = 0.0;
    for (int i = 0; i < M; ++i) {
        const double ca = std::pow(1.0 - (i + 0.5) / M, 1.0 / (k + 1.0));
        const double ta = std::sqrt(std::max(0.0, 1.0 - ca * ca)) / ca;
        const double c = ta > 0.0 ? -std::tan(beta) / ta : -kInf;
        sum += c <= -1.0 ? 1.0 : (c >= 1.0 ? 0.0 : std::acos(c) / M_PI);
    }
    return sum / M;
}

bool isLambertian(const Material& m) { return m.kind == BSDFKind::Diffuse || m.exponent == 0.0f; }

bool finiteColor(const Color& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

// Relative tolerance for comparing two evaluations of the Phong lobe that compute cos(alpha)
// with different float roundings: an absolute error of ~16 * 2^-24 in cos(alpha) (a reflection
// and a dot product) changes cos^k(alpha) by a relative k * 16 * 2^-24 / cos(alpha).
double phongRelTol(float k, double cosAlpha) { return 1e-5 + k * 16.0 * 0x1p-24 / std::max(cosAlpha, 1e-30); }

}  // namespace

TEST_CASE("bsdf: pdfBSDF integrates to 1 (diffuse) and to the lobe's probability above the surface (Phong)") {
    // Tolerance 1.5e-3: on the N x N = 768^2 grid of the lobe warp the integrand pdf/q is the
    // indicator of "above the surface" (1 where pdfBSDF equals the lobe density); each grid row
    // crosses the horizon at most twice, each crossing misjudging at most half a cell, so the
    // grid errs by <= 1/N = 1.3e-3. Lambertian (diffuse, Phong exponent 0): the grid is about
    // ns, where pdf/q = 2 cos(theta) is linear in the grid variable: the midpoint rule is exact.
    const int N = 768;
    for (float cosO : {1.0f, 0.5f, 1e-3f, -0.5f}) {
        const Vec3 wo = outgoing(cosO), ns = sideNormal(kNormal, wo);
        std::vector<Material> mats = {diffuse()};
        for (float k : kExponents) mats.push_back(phong(k));
        for (const Material& m : mats) {
            const bool lambert = isLambertian(m);
            const Vec3 axis = lambert ? ns : reflect(wo, ns);
            const double I = sphereIntegral([&](const Vec3& w) { return double(pdfBSDF(m, kNormal, wo, w)); }, axis,
                                            lambert ? 0.0 : m.exponent, N);
            const double P = lambert ? 1.0 : aboveProbability(m.exponent, cosO);
            CHECK_MESSAGE(std::abs(I - P) < 1.5e-3, (m.kind == BSDFKind::Diffuse ? "diffuse" : "Phong")
                                                        << " exponent " << m.exponent << ", cos(theta_o) = " << cosO
                                                        << ": expected " << P
                                                        << " (probability above the surface), got " << I);
        }
    }
}

TEST_CASE("bsdf: sampleBSDF's pdf equals pdfBSDF and its weight equals f |cos| / pdf") {
    // The pdf a sample reports must be the value pdfBSDF gives for its direction (MIS weights
    // combine the two; with cos^1e6 a rounding difference in cos(alpha) changes the pdf by
    // 20 %), so relative 1e-6; the weight is f |cos| / pdf to float rounding: relative 1e-5.
    Rng rng(testseed::seed(77));
    const int S = 20000;
    for (float cosO : kCosO) {
        const Vec3 wo = outgoing(cosO), ns = sideNormal(kNormal, wo);
        std::vector<Material> mats = {diffuse()};
        for (float k : kExponents) mats.push_back(phong(k));
        for (const Material& m : mats) {
            int bad = 0, valid = 0;
            for (int i = 0; i < S; ++i) {
                const Vec2 u = rng.uniform2();
                const float uLobe = rng.uniform();
                BSDFSample s;
                if (!sampleBSDF(m, kNormal, wo, u, uLobe, Transport::Radiance, s)) continue;
                ++valid;
                const float pdf = pdfBSDF(m, kNormal, wo, s.wi);
                const Color f = evalBSDF(m, kNormal, wo, s.wi);
                const float cosI = std::abs(glm::dot(kNormal, s.wi));
                const Color expectW = f * cosI / s.pdf;
                const bool ok = !s.delta && std::abs(glm::length(s.wi) - 1.0f) < 1e-5f && glm::dot(ns, s.wi) > 0.0f &&
                                std::abs(s.pdf - pdf) <= 1e-6f * pdf &&
                                std::abs(s.weight.g - expectW.g) <= 1e-5f * expectW.g + 1e-30f;
                if (!ok && ++bad <= 3)
                    FAIL_CHECK((m.kind == BSDFKind::Diffuse ? "diffuse" : "Phong")
                               << " exponent " << m.exponent << ", cos(theta_o) " << cosO << ": sample pdf " << s.pdf
                               << " vs pdfBSDF " << pdf << ", weight " << s.weight.g << " vs f|cos|/pdf " << expectW.g
                               << ", |wi| " << glm::length(s.wi) << ", ns.wi " << glm::dot(ns, s.wi));
            }
            INFO("material exponent " << m.exponent << " kind " << int(m.kind) << ", cos(theta_o) = " << cosO);
            CHECK(bad == 0);
            // The fraction of valid samples is the probability of landing above the surface:
            // binomial, 5 standard errors (+1e-3 for the quadrature of the reference).
            const double P = isLambertian(m) ? 1.0 : aboveProbability(m.exponent, cosO);
            const double frac = double(valid) / S, tol = 5.0 * std::sqrt(P * (1.0 - P) / S) + 1e-3;
            CHECK_MESSAGE(std::abs(frac - P) < tol,
                          "valid fraction: expected " << P << " +- " << tol << ", got " << frac);
        }
    }
}

TEST_CASE("bsdf: evalBSDF is reciprocal and pdf is 0 exactly where f is 0") {
    Rng rng(testseed::seed(78));
    for (float k : kExponents) {
        const Material ms[] = {diffuse(), phong(k)};
        for (const Material& m : ms) {
            int notReciprocal = 0, zeroMismatch = 0;
            for (int i = 0; i < 20000; ++i) {
                const float cosO = kCosO[i % 6];
                const Vec3 wo = outgoing(cosO), ns = sideNormal(kNormal, wo);
                // wi near the lobe (a lobe sample) half the time, anywhere otherwise.
                Vec3 wi;
                BSDFSample s;
                if (i % 2 && sampleBSDF(m, kNormal, wo, rng.uniform2(), 0.5f, Transport::Radiance, s)) wi = s.wi;
                else {
                    const double u1 = rng.uniform(), u2 = rng.uniform();
                    wi = dirAround(ns, 2.0 * u1 - 1.0, 2.0 * M_PI * u2);
                }
                const float a = evalBSDF(m, kNormal, wo, wi).g, b = evalBSDF(m, kNormal, wi, wo).g;
                const double cosAlpha = glm::dot(glm::dvec3(reflect(wo, ns)), glm::dvec3(wi));
                // (+1e-38: values below FLT_MIN are denormal and keep fewer significant bits.)
                const double tol = isLambertian(m) ? 0.0 : phongRelTol(k, cosAlpha) * std::max(a, b) + 1e-38;
                if (std::abs(a - b) > tol && ++notReciprocal <= 3)
                    FAIL_CHECK("exponent " << m.exponent << ": f(wo, wi) = " << a << " but f(wi, wo) = " << b);
                const float pdf = pdfBSDF(m, kNormal, wo, wi);
                if ((a == 0.0f) != (pdf == 0.0f) && ++zeroMismatch <= 3)
                    FAIL_CHECK("exponent " << m.exponent << ": f = " << a << " but pdf = " << pdf);
            }
            INFO((m.kind == BSDFKind::Diffuse ? "diffuse" : "Phong") << " exponent " << m.exponent);
            CHECK(notReciprocal == 0);
            CHECK(zeroMismatch == 0);
        }
    }
}

namespace {
// Mean sample weight over a stratified N x N grid of u (invalid samples count 0): the
// directional albedo R(wo) = integral of f |cos| over wi.
double meanWeight(const Material& m, const Vec3& wo, int N) {
    double sum = 0.0;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            BSDFSample s;
            if (sampleBSDF(m, kNormal, wo, Vec2((i + 0.5f) / N, (j + 0.5f) / N), 0.5f, Transport::Radiance, s))
                sum += s.weight.g;
        }
    return sum / (double(N) * N);
}
}  // namespace

TEST_CASE("bsdf: albedo (mean sample weight) is at most 1, equals the albedo for diffuse") {
    // Expected directional albedo R(wo):
    //  - Lambertian (diffuse, Phong exponent 0): every weight equals the albedo: R = albedo;
    //  - Phong at normal incidence: the lobe lies above the surface and the weight is
    //    (n+2)/(n+1) cos(alpha), E[cos(alpha)] = (n+1)/(n+2) under the lobe: R = albedo exactly;
    //  - Phong, n >= 100, |cos(theta_o)| >= 0.5: the lobe's mass below the surface is
    //    ~cos^101(60 deg) = 2^-101, so R = (n+2)/(n+1) E[ns . wi] = albedo |cos(theta_o)|;
    //  - always R <= albedo <= 1 (energy conservation).
    // Tolerances: Lambertian 1e-6 (exact up to summation). Phong: the weight is smooth in u
    // except where the lobe crosses the horizon; at normal incidence the only roughness is the
    // cos(alpha) = (1-u)^(1/(n+1)) cusp at u = 1, whose midpoint error is ~N^-1.5 = 1e-4
    // (N = 512): tolerance 1e-3. For the bound R <= 1, the horizon crossing adds at most
    // 2 cells per row with weights <= 2: 4/N ~ 8e-3, which we allow.
    const int N = 512;
    for (float cosO : kCosO) {
        const Vec3 wo = outgoing(cosO);
        const double Rd = meanWeight(diffuse(0.63f), wo, N);
        CHECK_MESSAGE(std::abs(Rd - 0.63) < 1e-6, "diffuse albedo 0.63, cos(theta_o) " << cosO << ": got " << Rd);
        for (float k : kExponents) {
            const double R = meanWeight(phong(k, 1.0f), wo, N);
            INFO("Phong exponent " << k << ", albedo 1, cos(theta_o) = " << cosO);
            CHECK_MESSAGE(R <= 1.0 + 8e-3, "expected R <= 1, got " << R);
            if (k == 0.0f)
                CHECK_MESSAGE(std::abs(R - 1.0) < 1e-6, "exponent 0 (Lambertian): expected R = 1, got " << R);
            if (cosO == 1.0f) CHECK_MESSAGE(std::abs(R - 1.0) < 1e-3, "normal incidence: expected R = 1, got " << R);
            if (k >= 100.0f && std::abs(cosO) >= 0.5f)
                CHECK_MESSAGE(std::abs(R - std::abs(cosO)) < 1e-3,
                              "expected R = |cos(theta_o)| = " << std::abs(cosO) << ", got " << R);
        }
    }
}

TEST_CASE("bsdf: Phong with exponent 0 is Lambertian") {
    // The framework's promise (bsdf.cpp): normalized Phong f = albedo (n+2)/(2 pi) cos^n(alpha)
    // with n = 0 is albedo / pi, the Lambertian BRDF, for every pair of directions on one side.
    Rng rng(testseed::seed(79));
    const Material p = phong(0.0f, 0.6f), d = diffuse(0.6f);
    for (float cosO : kCosO) {
        const Vec3 wo = outgoing(cosO), ns = sideNormal(kNormal, wo);
        int bad = 0;
        for (int i = 0; i < 2000; ++i) {
            const double u1 = rng.uniform(), u2 = rng.uniform();
            const Vec3 wi = dirAround(ns, 0.001 + 0.999 * u1, 2.0 * M_PI * u2);
            const float fp = evalBSDF(p, kNormal, wo, wi).g, fd = evalBSDF(d, kNormal, wo, wi).g;
            if (std::abs(fp - fd) > 1e-6f * fd && ++bad <= 3)
                FAIL_CHECK("cos(theta_o) = " << cosO << ", cos(theta_i) = " << glm::dot(ns, wi)
                                             << ": Phong(0) f = " << fp << ", Lambertian f = " << fd);
        }
        CHECK_MESSAGE(bad == 0, "cos(theta_o) = " << cosO << ": " << bad << " of 2000 directions differ");
    }
}

TEST_CASE("bsdf: no NaN or Inf for exponents up to 1e6 and grazing or signed-zero directions") {
    // Directions with cos(theta) in {1, 1e-3, 1e-7, +0, -0, -1e-7, -1e-3, -1} about n = +z (so
    // that +-0 are exact), and u at the ends of [0, 1).
    const Vec3 n(0, 0, 1);
    std::vector<Vec3> dirs;
    for (float c : {1.0f, 1e-3f, 1e-7f, 0.0f, -0.0f, -1e-7f, -1e-3f, -1.0f})
        for (float phi : {0.0f, 1.3f, 4.0f}) {
            const float s = std::sqrt(1.0f - c * c);
            dirs.push_back(Vec3(s * std::cos(phi), s * std::sin(phi), c));
        }
    const Vec2 us[] = {Vec2(0.0f),        Vec2(0x1.fffffep-1f), Vec2(0.0f, 0x1.fffffep-1f), Vec2(0x1.fffffep-1f, 0.0f),
                       Vec2(0.5f, 0.25f), Vec2(1e-7f, 0.5f),    Vec2(1.0f - 1e-7f, 0.5f)};
    std::vector<Material> mats = {diffuse(), mirror(), glass(1.5f), glass(1.0f / 1.5f)};
    for (float k : kExponents) mats.push_back(phong(k, 1.0f));
    int bad = 0;
    for (const Material& m : mats)
        for (const Vec3& wo : dirs) {
            for (const Vec3& wi : dirs) {
                const Color f = evalBSDF(m, n, wo, wi);
                const float pdf = pdfBSDF(m, n, wo, wi);
                if ((!finiteColor(f) || !(pdf >= 0.0f) || !std::isfinite(pdf) || f.g < 0.0f) && ++bad <= 5)
                    FAIL_CHECK("kind " << int(m.kind) << " exponent " << m.exponent << ": f = " << f.g
                                       << ", pdf = " << pdf << " for wo.z = " << wo.z << ", wi.z = " << wi.z);
            }
            for (const Vec2& u : us)
                for (float uLobe : {0.0f, 0.5f, 0x1.fffffep-1f})
                    for (Transport mode : {Transport::Radiance, Transport::Importance}) {
                        BSDFSample s;
                        if (!sampleBSDF(m, n, wo, u, uLobe, mode, s)) continue;
                        const bool ok = finiteColor(s.weight) && s.weight.g >= 0.0f && std::isfinite(s.pdf) &&
                                        s.pdf > 0.0f && std::isfinite(s.wi.x) && std::isfinite(s.wi.y) &&
                                        std::isfinite(s.wi.z) && std::abs(glm::length(s.wi) - 1.0f) < 1e-5f;
                        if (!ok && ++bad <= 5)
                            FAIL_CHECK("kind " << int(m.kind) << " exponent " << m.exponent << ": sample from wo.z = "
                                               << wo.z << " gave wi = (" << s.wi.x << ", " << s.wi.y << ", " << s.wi.z
                                               << "), pdf " << s.pdf << ", weight " << s.weight.g);
                    }
        }
    CHECK(bad == 0);
}

TEST_CASE("bsdf: mirror is a delta lobe that reflects exactly") {
    const Material m = mirror();
    CHECK(m.isDelta());
    CHECK_FALSE(diffuse().isDelta());
    CHECK_FALSE(phong(1e6f).isDelta());
    Rng rng(testseed::seed(80));
    for (float cosO : kCosO) {
        const Vec3 wo = outgoing(cosO);
        const Vec2 u = rng.uniform2();
        const float uLobe = rng.uniform();
        BSDFSample s;
        REQUIRE(sampleBSDF(m, kNormal, wo, u, uLobe, Transport::Radiance, s));
        // wi = 2 (wo . n) n - wo: equal angles, same plane, other side of n.
        const Vec3 expect = 2.0f * glm::dot(wo, kNormal) * kNormal - wo;
        INFO("cos(theta_o) = " << cosO);
        CHECK_MESSAGE(glm::length(s.wi - expect) < 1e-6f, "wi = (" << s.wi.x << ", " << s.wi.y << ", " << s.wi.z
                                                                   << "), expected (" << expect.x << ", " << expect.y
                                                                   << ", " << expect.z << ")");
        CHECK(glm::dot(s.wi, kNormal) == doctest::Approx(glm::dot(wo, kNormal)).epsilon(1e-5));
        CHECK(s.delta);
        CHECK(s.weight == m.albedo);
        // A delta lobe has no density: f and pdf are 0, even for the exact mirror pair.
        CHECK(isBlack(evalBSDF(m, kNormal, wo, s.wi)));
        CHECK(pdfBSDF(m, kNormal, wo, s.wi) == 0.0f);
        CHECK(isBlack(evalBSDF(glass(1.5f), kNormal, wo, s.wi)));
        CHECK(pdfBSDF(glass(1.5f), kNormal, wo, s.wi) == 0.0f);
    }
}

namespace {
// The textbook Fresnel reflectance for unpolarised light, in double (Born & Wolf):
// Rs = ((ni ci - nt ct) / (ni ci + nt ct))^2, Rp = ((ni ct - nt ci) / (ni ct + nt ci))^2.
double fresnelRef(double ci, double ni, double nt) {
    const double s2 = (ni / nt) * (ni / nt) * (1.0 - ci * ci);
    if (s2 >= 1.0) return 1.0;
    const double ct = std::sqrt(1.0 - s2);
    const double rs = (ni * ci - nt * ct) / (ni * ci + nt * ct), rp = (ni * ct - nt * ci) / (ni * ct + nt * ci);
    return 0.5 * (rs * rs + rp * rp);
}
}  // namespace

TEST_CASE("bsdf: dielectric Fresnel at normal incidence and against the textbook formula") {
    for (float ior : {1.33f, 1.5f, 2.4f}) {
        const double r0 = std::pow((ior - 1.0) / (ior + 1.0), 2.0);  // ((n-1)/(n+1))^2
        CHECK_MESSAGE(
            fresnelDielectric(1.0f, 1.0f, ior) == doctest::Approx(r0).epsilon(1e-5),
            "ior " << ior << " from outside: expected " << r0 << ", got " << fresnelDielectric(1.0f, 1.0f, ior));
        CHECK_MESSAGE(
            fresnelDielectric(1.0f, ior, 1.0f) == doctest::Approx(r0).epsilon(1e-5),
            "ior " << ior << " from inside: expected " << r0 << ", got " << fresnelDielectric(1.0f, ior, 1.0f));
        for (int i = 0; i <= 100; ++i) {
            const float c = i / 100.0f;
            for (const std::pair<float, float>& eta : {std::pair<float, float>{1.0f, ior}, {ior, 1.0f}}) {
                const float ni = eta.first, nt = eta.second;  // named, not bound: clang < 16 captures no binding
                const double ref = fresnelRef(c, ni, nt);
                CHECK_MESSAGE(std::abs(fresnelDielectric(c, ni, nt) - ref) < 1e-5,
                              "cos " << c << ", eta " << ni << " -> " << nt << ": expected " << ref << ", got "
                                     << fresnelDielectric(c, ni, nt));
            }
        }
    }
}

TEST_CASE("bsdf: dielectric total internal reflection beyond the critical angle") {
    // From inside (wo on the side opposite n, index 1.5 -> 1): sin(theta_c) = 1/1.5.
    const Material m = glass(1.5f);
    CHECK(m.isDelta());
    const double cosCrit = std::sqrt(1.0 - 1.0 / (1.5 * 1.5));
    for (double f : {0.999, 0.9, 0.5, 0.1, 1e-3}) {
        const float cosO = static_cast<float>(-cosCrit * f);  // beyond the critical angle
        const Vec3 wo = outgoing(cosO);
        CHECK(fresnelDielectric(-cosO, 1.5f, 1.0f) == 1.0f);
        for (float uLobe : {0.0f, 0.5f, 0.99f, 0x1.fffffep-1f}) {
            BSDFSample s;
            REQUIRE(sampleBSDF(m, kNormal, wo, Vec2(0.5f), uLobe, Transport::Radiance, s));
            INFO("cos(theta_o) = " << cosO << ", uLobe = " << uLobe);
            CHECK_MESSAGE(glm::dot(s.wi, kNormal) < 0.0f,
                          "expected reflection (wi inside), got n.wi = " << glm::dot(s.wi, kNormal));
            CHECK(glm::length(s.wi - reflect(wo, -kNormal)) < 1e-6f);
            CHECK(s.weight == Color(1.0f));
            CHECK(s.pdf == 1.0f);
            CHECK(s.delta);
        }
    }
}

TEST_CASE("bsdf: dielectric refraction obeys Snell's law, transport weights and lobe probabilities") {
    const Material m = glass(1.5f);
    const int M = 10000;                                                  // uLobe grid for the lobe probabilities
    for (float cosO : {1.0f, 0.8f, 0.3f, 0.01f, -1.0f, -0.9f, -0.76f}) {  // -0.76: just inside the critical cone
        const Vec3 wo = outgoing(cosO);
        const bool entering = cosO > 0.0f;
        const float etaI = entering ? 1.0f : 1.5f, etaT = entering ? 1.5f : 1.0f;
        const float F = fresnelDielectric(std::abs(cosO), etaI, etaT);
        INFO("cos(theta_o) = " << cosO << ", F = " << F);
        REQUIRE(F < 1.0f);
        int reflected = 0;
        for (int i = 0; i < M; ++i) {
            const float uLobe = (i + 0.5f) / M;
            for (Transport mode : {Transport::Radiance, Transport::Importance}) {
                BSDFSample s;
                REQUIRE(sampleBSDF(m, kNormal, wo, Vec2(0.3f), uLobe, mode, s));
                REQUIRE(s.delta);
                const bool refl = glm::dot(s.wi, kNormal) * glm::dot(wo, kNormal) > 0.0f;
                if (mode == Transport::Radiance) reflected += refl;
                if (refl) {
                    CHECK(s.pdf == doctest::Approx(F));
                    CHECK(s.weight == Color(1.0f));
                    continue;
                }
                CHECK(s.pdf == doctest::Approx(1.0f - F));
                // Snell: etaI sin(theta_i) = etaT sin(theta_t), wi in the plane of wo and n,
                // on the far side, its tangential part opposite to wo's.
                const float sinI = glm::length(glm::cross(kNormal, wo)), sinT = glm::length(glm::cross(kNormal, s.wi));
                CHECK_MESSAGE(std::abs(etaI * sinI - etaT * sinT) < 1e-5f,
                              "Snell: " << etaI * sinI << " vs " << etaT * sinT);
                CHECK(std::abs(glm::dot(glm::cross(wo, kNormal), s.wi)) < 1e-5f);
                CHECK(glm::dot(wo - glm::dot(wo, kNormal) * kNormal, s.wi - glm::dot(s.wi, kNormal) * kNormal) <=
                      1e-6f);
                CHECK(std::abs(glm::length(s.wi) - 1.0f) < 1e-5f);
                // Radiance is scaled by (etaI/etaT)^2 on crossing; importance is not.
                const float expectW = mode == Transport::Radiance ? (etaI / etaT) * (etaI / etaT) : 1.0f;
                CHECK_MESSAGE(s.weight.g == doctest::Approx(expectW),
                              "weight: expected " << expectW << ", got " << s.weight.g);
            }
        }
        // Reflection is chosen for a fraction F of uLobe, refraction for 1 - F: they sum to 1.
        CHECK_MESSAGE(std::abs(double(reflected) / M - F) <= 1.0 / M,
                      "reflected fraction " << double(reflected) / M << ", F = " << F);
        BSDFSample r, t;
        REQUIRE(sampleBSDF(m, kNormal, wo, Vec2(0.3f), 0.0f, Transport::Radiance, r));
        REQUIRE(sampleBSDF(m, kNormal, wo, Vec2(0.3f), 0x1.fffffep-1f, Transport::Radiance, t));
        if (F > 0.0f)
            CHECK_MESSAGE(r.pdf + t.pdf == doctest::Approx(1.0f), "P(reflect) + P(refract) = " << r.pdf + t.pdf);
    }
}

TEST_CASE("bsdf: diffuse sampling never loses a sample to the disk's rim (u with a coordinate exactly 0)") {
    // Lesson 1's concentric map sends u.x = 0 or u.y = 0 (a or b = -1) to the disk's rim, where
    // cos(theta) = 0 and the pdf is 0: sampleBSDF once returned false there, ending a path
    // (1.2e-7 per bounce, 1.2 % of the paths at albedo 1 and depth 1e5). cosineWarpU keeps u off
    // those values; every u the sampler gives (multiples of 2^-24) must give a usable sample.
    const Vec2 us[] = {Vec2(0.0f, 0.3f),           Vec2(0.3f, 0.0f), Vec2(0.0f),       Vec2(0.0f, 0x1.fffffep-1f),
                       Vec2(0x1.fffffep-1f, 0.0f), Vec2(0.0f, 0.5f), Vec2(0.5f, 0.0f), Vec2(0x1p-24f, 0.7f)};
    const Vec3 normals[] = {Vec3(0, 0, 1), Vec3(0, -1, 0), Vec3(1, 0, 0), glm::normalize(Vec3(0.3f, -0.8f, 0.52f))};
    for (const Vec3& n : normals)
        for (const Vec2& u : us) {
            const Vec3 wo = glm::normalize(n + Vec3(0.1f, 0.2f, 0.05f));
            for (const Material& m : {diffuse(), phong(0.0f, 1.0f)}) {
                BSDFSample s;
                const bool ok = sampleBSDF(m, n, wo, u, 0.5f, Transport::Radiance, s);
                CHECK_MESSAGE((ok && s.pdf > 0.0f && glm::dot(s.wi, n) > 0.0f),
                              "u = (" << u.x << ", " << u.y << "), n = (" << n.x << ", " << n.y << ", " << n.z
                                      << "): sample lost (pdf " << s.pdf << ")");
            }
        }
}
