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
    //! TODO(01) A unit direction, uniform over the sphere (Eq. 1.8).
    //! STUB (void)u;
    //! STUB return PS_TODO("lesson 01: sampleUniformSphere", Vec3(0.0f, 0.0f, 1.0f));
    //! BEGIN
    const float z = 1.0f - 2.0f * u.x;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = kTwoPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
    //! END
}

float uniformSpherePdf() {
    //! TODO(01) The density of Eq. 1.8's samples per unit solid angle.
    //! STUB return PS_TODO("lesson 01: uniformSpherePdf", 0.0f);
    //! BEGIN
    return 1.0f / (4.0f * kPi);
    //! END
}

Vec2 invertUniformSphere(const Vec3& w) {
    //! TODO(01) The u in [0, 1)^2 that Eq. 1.8 maps to w; angles from atan2 go through turns() (README, Pitfalls).
    //! STUB (void)w;
    //! STUB return PS_TODO("lesson 01: invertUniformSphere", Vec2(0.0f));
    //! BEGIN
    return Vec2((1.0f - w.z) * 0.5f, turns(w.x, w.y));
    //! END
}

Vec3 sampleUniformHemisphere(const Vec2& u) {
    //! TODO(01) A unit direction, uniform over the hemisphere z >= 0 (Eq. 1.9).
    //! STUB (void)u;
    //! STUB return PS_TODO("lesson 01: sampleUniformHemisphere", Vec3(0.0f, 0.0f, 1.0f));
    //! BEGIN
    const float z = u.x;
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = kTwoPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
    //! END
}

float uniformHemispherePdf(const Vec3& w) {
    //! TODO(01) Its density per unit solid angle (Eq. 1.9); 0 below the horizon: the tests integrate over the sphere.
    //! STUB (void)w;
    //! STUB return PS_TODO("lesson 01: uniformHemispherePdf", 0.0f);
    //! BEGIN
    return w.z > 0.0f ? 1.0f / kTwoPi : 0.0f;
    //! END
}

Vec2 invertUniformHemisphere(const Vec3& w) {
    //! TODO(01) The u in [0, 1)^2 that Eq. 1.9 maps to w (angles through turns()).
    //! STUB (void)w;
    //! STUB return PS_TODO("lesson 01: invertUniformHemisphere", Vec2(0.0f));
    //! BEGIN
    return Vec2(w.z, turns(w.x, w.y));
    //! END
}

Vec2 sampleConcentricDisk(const Vec2& u) {
    //! TODO(01) A point uniform per unit area in the unit disk by the concentric map (Eq. 1.10): all four wedges.
    //! STUB (void)u;
    //! STUB return PS_TODO("lesson 01: sampleConcentricDisk", Vec2(0.0f));
    //! BEGIN
    const float a = 2.0f * u.x - 1.0f, b = 2.0f * u.y - 1.0f;
    if (a == 0.0f && b == 0.0f) return Vec2(0.0f);
    float r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = (kPi / 4.0f) * (b / a);
    } else {
        r = b;
        phi = kPi / 2.0f - (kPi / 4.0f) * (a / b);
    }
    return Vec2(r * std::cos(phi), r * std::sin(phi));
    //! END
}

float concentricDiskPdf(const Vec2& p) {
    //! TODO(01) Its density per unit area (Eq. 1.10), 0 outside the disk.
    //! STUB (void)p;
    //! STUB return PS_TODO("lesson 01: concentricDiskPdf", 0.0f);
    //! BEGIN
    return glm::dot(p, p) <= 1.0f ? kInvPi : 0.0f;
    //! END
}

Vec2 invertConcentricDisk(const Vec2& p) {
    //! TODO(01) The u in [0, 1)^2 that Eq. 1.10 maps to p: the wedge follows from p's angle.
    //! STUB (void)p;
    //! STUB return PS_TODO("lesson 01: invertConcentricDisk", Vec2(0.0f));
    //! BEGIN
    const float r = std::sqrt(p.x * p.x + p.y * p.y);
    float phi = std::atan2(p.y, p.x);
    if (phi < -kPi / 4.0f) phi += 2.0f * kPi;  // phi in [-pi/4, 7pi/4)
    float a, b;
    if (phi < kPi / 4.0f) {  // right wedge: r = a, phi = pi/4 b/a
        a = r;
        b = phi * a / (kPi / 4.0f);
    } else if (phi < 3.0f * kPi / 4.0f) {  // top: r = b, phi = pi/2 - pi/4 a/b
        b = r;
        a = -(phi - kPi / 2.0f) * b / (kPi / 4.0f);
    } else if (phi < 5.0f * kPi / 4.0f) {  // left: r = -a (a < 0), phi - pi = pi/4 b/a
        a = -r;
        b = (phi - kPi) * a / (kPi / 4.0f);
    } else {  // bottom: r = -b, phi - 3pi/2 = -pi/4 a/b
        b = -r;
        a = -(phi - 3.0f * kPi / 2.0f) * b / (kPi / 4.0f);
    }
    return Vec2(glm::clamp((a + 1.0f) * 0.5f, 0.0f, 1.0f), glm::clamp((b + 1.0f) * 0.5f, 0.0f, 1.0f));
    //! END
}

Vec3 sampleCosineHemisphere(const Vec2& u) {
    //! TODO(01) A unit direction with density cos(theta) / pi per solid angle (Eq. 1.11); clamp before sqrt (Pitfalls).
    //! STUB (void)u;
    //! STUB return PS_TODO("lesson 01: sampleCosineHemisphere", Vec3(0.0f, 0.0f, 1.0f));
    //! BEGIN
    const Vec2 d = sampleConcentricDisk(u);
    return Vec3(d.x, d.y, std::sqrt(std::max(0.0f, 1.0f - d.x * d.x - d.y * d.y)));
    //! END
}

float cosineHemispherePdf(const Vec3& w) {
    //! TODO(01) Its density per unit solid angle (Eq. 1.11), 0 below the horizon.
    //! STUB (void)w;
    //! STUB return PS_TODO("lesson 01: cosineHemispherePdf", 0.0f);
    //! BEGIN
    return w.z > 0.0f ? w.z * kInvPi : 0.0f;
    //! END
}

Vec2 invertCosineHemisphere(const Vec3& w) {
    //! TODO(01) The u in [0, 1)^2 that Eq. 1.11 maps to w.
    //! STUB (void)w;
    //! STUB return PS_TODO("lesson 01: invertCosineHemisphere", Vec2(0.0f));
    //! BEGIN
    return invertConcentricDisk(Vec2(w.x, w.y));
    //! END
}

Vec3 samplePhongLobe(const Vec2& u, float exponent) {
    //! TODO(01) A unit direction around +z with Eq. 1.12's density per solid angle; finite for n up to 1e6 and never
    //!          on the horizon (README, Pitfalls: "Float u is never 1").
    //! STUB (void)u; (void)exponent;
    //! STUB return PS_TODO("lesson 01: samplePhongLobe", Vec3(0.0f, 0.0f, 1.0f));
    //! BEGIN
    const float c = std::pow(1.0f - u.x, 1.0f / (exponent + 1.0f));  // 1 - u.x in (0, 1]
    const float s = std::sqrt(std::max(0.0f, 1.0f - c * c)), phi = kTwoPi * u.y;
    return Vec3(s * std::cos(phi), s * std::sin(phi), c);
    //! END
}

float phongLobePdf(const Vec3& w, float exponent) {
    //! TODO(01) Eq. 1.12's density per unit solid angle, 0 below the horizon.
    //! STUB (void)w; (void)exponent;
    //! STUB return PS_TODO("lesson 01: phongLobePdf", 0.0f);
    //! BEGIN
    return w.z > 0.0f ? (exponent + 1.0f) / kTwoPi * std::pow(w.z, exponent) : 0.0f;
    //! END
}

Vec2 invertPhongLobe(const Vec3& w, float exponent) {
    //! TODO(01) The u in [0, 1)^2 that Eq. 1.12 maps to w.
    //! STUB (void)w; (void)exponent;
    //! STUB return PS_TODO("lesson 01: invertPhongLobe", Vec2(0.0f));
    //! BEGIN
    return Vec2(1.0f - std::pow(std::max(0.0f, w.z), exponent + 1.0f), turns(w.x, w.y));
    //! END
}

Vec2 sampleUniformTriangle(const Vec2& u) {
    //! TODO(01) Barycentrics (b1, b2) uniform over the triangle (Eq. 1.13).
    //! STUB (void)u;
    //! STUB return PS_TODO("lesson 01: sampleUniformTriangle", Vec2(0.0f));
    //! BEGIN
    const float s = std::sqrt(u.x);
    return Vec2(s * (1.0f - u.y), s * u.y);
    //! END
}

Vec2 invertUniformTriangle(const Vec2& b) {
    //! TODO(01) The u that Eq. 1.13 maps to b; the corner b = (0, 0) gives u = (0, 0), not NaN.
    //! STUB (void)b;
    //! STUB return PS_TODO("lesson 01: invertUniformTriangle", Vec2(0.0f));
    //! BEGIN
    const float s = b.x + b.y;
    return Vec2(s * s, s > 0.0f ? b.y / s : 0.0f);
    //! END
}

}  // namespace ps
