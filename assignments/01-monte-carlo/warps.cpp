// Lesson 1 — Monte Carlo integration: the warps. Interface: framework/warps.h.
// Equation numbers refer to lessons/01-monte-carlo/README.md.
#include "todo.h"
#include "warps.h"

namespace ps {

namespace {
constexpr float kTwoPi = 2.0f * kPi;
// Angle of (x, y) in [0, 1) turns (for the inverses).
[[maybe_unused]] float turns(float x, float y) {
    float t = std::atan2(y, x) / kTwoPi;
    return t < 0.0f ? t + 1.0f : (t >= 1.0f ? 0.0f : t);
}
}  // namespace

Vec3 sampleUniformSphere(const Vec2& u) {
    // TODO(01) z = 1 - 2 u.x, phi = 2 pi u.y (Eq. 1.8); return the unit vector.
    (void)u;
    return PS_TODO("lesson 01: sampleUniformSphere", Vec3(0.0f, 0.0f, 1.0f));
}

float uniformSpherePdf() {
    // TODO(01) The constant pdf per unit solid angle (Eq. 1.8).
    return PS_TODO("lesson 01: uniformSpherePdf", 0.0f);
}

Vec2 invertUniformSphere(const Vec3& w) {
    // TODO(01) Invert Eq. 1.8: u.x from z; u.y = phi / (2 pi) in [0, 1), which turns(w.x, w.y)
    //          above computes.
    (void)w;
    return PS_TODO("lesson 01: invertUniformSphere", Vec2(0.0f));
}

Vec3 sampleUniformHemisphere(const Vec2& u) {
    // TODO(01) z = u.x, phi = 2 pi u.y (Eq. 1.9).
    (void)u;
    return PS_TODO("lesson 01: sampleUniformHemisphere", Vec3(0.0f, 0.0f, 1.0f));
}

float uniformHemispherePdf(const Vec3& w) {
    // TODO(01) 1 / (2 pi) above the horizon (z > 0), 0 elsewhere (Eq. 1.9).
    (void)w;
    return PS_TODO("lesson 01: uniformHemispherePdf", 0.0f);
}

Vec2 invertUniformHemisphere(const Vec3& w) {
    // TODO(01) Invert Eq. 1.9: u.x from z, u.y = turns(w.x, w.y).
    (void)w;
    return PS_TODO("lesson 01: invertUniformHemisphere", Vec2(0.0f));
}

Vec2 sampleConcentricDisk(const Vec2& u) {
    // TODO(01) Map u to [-1,1]^2, then each of the four wedges to a sector of the disk:
    //          r = a, phi = pi/4 * b/a where |a| > |b|, and the mirror case (Eq. 1.10).
    (void)u;
    return PS_TODO("lesson 01: sampleConcentricDisk", Vec2(0.0f));
}

float concentricDiskPdf(const Vec2& p) {
    // TODO(01) 1 / pi inside the unit disk, 0 outside (Eq. 1.10).
    (void)p;
    return PS_TODO("lesson 01: concentricDiskPdf", 0.0f);
}

Vec2 invertConcentricDisk(const Vec2& p) {
    // TODO(01) Invert Eq. 1.10: find the wedge from phi, recover (a, b), map back to [0,1)^2.
    (void)p;
    return PS_TODO("lesson 01: invertConcentricDisk", Vec2(0.0f));
}

Vec3 sampleCosineHemisphere(const Vec2& u) {
    // TODO(01) Malley's method (Eq. 1.11): a uniform point on the disk, projected up to the
    //          hemisphere (z = sqrt(1 - x^2 - y^2)).
    (void)u;
    return PS_TODO("lesson 01: sampleCosineHemisphere", Vec3(0.0f, 0.0f, 1.0f));
}

float cosineHemispherePdf(const Vec3& w) {
    // TODO(01) cos(theta) / pi above the horizon, 0 elsewhere (Eq. 1.11).
    (void)w;
    return PS_TODO("lesson 01: cosineHemispherePdf", 0.0f);
}

Vec2 invertCosineHemisphere(const Vec3& w) {
    // TODO(01) Invert Eq. 1.11: drop z, then invert the disk map.
    (void)w;
    return PS_TODO("lesson 01: invertCosineHemisphere", Vec2(0.0f));
}

Vec3 samplePhongLobe(const Vec2& u, float exponent) {
    // TODO(01) Invert the CDF of cos(alpha): cos(alpha) = (1 - u.x)^(1/(n+1)), phi = 2 pi u.y
    //          (Eq. 1.12). Keep it finite for n up to 1e6.
    (void)u; (void)exponent;
    return PS_TODO("lesson 01: samplePhongLobe", Vec3(0.0f, 0.0f, 1.0f));
}

float phongLobePdf(const Vec3& w, float exponent) {
    // TODO(01) (n + 1) / (2 pi) cos^n(alpha) for cos(alpha) = w.z > 0, else 0 (Eq. 1.12).
    (void)w; (void)exponent;
    return PS_TODO("lesson 01: phongLobePdf", 0.0f);
}

Vec2 invertPhongLobe(const Vec3& w, float exponent) {
    // TODO(01) Invert Eq. 1.12: u.x = 1 - cos^(n+1)(alpha) with cos(alpha) = w.z,
    //          u.y = turns(w.x, w.y).
    (void)w; (void)exponent;
    return PS_TODO("lesson 01: invertPhongLobe", Vec2(0.0f));
}

Vec2 sampleUniformTriangle(const Vec2& u) {
    // TODO(01) Eq. 1.13: s = sqrt(u.x) is how far across the triangle (from the first corner)
    //          the point lies, u.y where along that segment; return (b1, b2) = s (1 - u.y, u.y).
    (void)u;
    return PS_TODO("lesson 01: sampleUniformTriangle", Vec2(0.0f));
}

Vec2 invertUniformTriangle(const Vec2& b) {
    // TODO(01) Invert Eq. 1.13: s = b1 + b2 gives u.x = s^2 and u.y = b2 / s (u.y = 0 when
    //          s = 0).
    (void)b;
    return PS_TODO("lesson 01: invertUniformTriangle", Vec2(0.0f));
}

}  // namespace ps
