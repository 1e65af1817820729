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
    // TODO(01) A unit direction, uniform over the sphere (Eq. 1.8).
    (void)u;
    return PS_TODO("lesson 01: sampleUniformSphere", Vec3(0.0f, 0.0f, 1.0f));
}

float uniformSpherePdf() {
    // TODO(01) The density of Eq. 1.8's samples per unit solid angle.
    return PS_TODO("lesson 01: uniformSpherePdf", 0.0f);
}

Vec2 invertUniformSphere(const Vec3& w) {
    // TODO(01) The u in [0, 1)^2 that Eq. 1.8 maps to w; angles from atan2 go through turns() (README, Pitfalls).
    (void)w;
    return PS_TODO("lesson 01: invertUniformSphere", Vec2(0.0f));
}

Vec3 sampleUniformHemisphere(const Vec2& u) {
    // TODO(01) A unit direction, uniform over the hemisphere z >= 0 (Eq. 1.9).
    (void)u;
    return PS_TODO("lesson 01: sampleUniformHemisphere", Vec3(0.0f, 0.0f, 1.0f));
}

float uniformHemispherePdf(const Vec3& w) {
    // TODO(01) Its density per unit solid angle (Eq. 1.9); 0 below the horizon: the tests integrate over the sphere.
    (void)w;
    return PS_TODO("lesson 01: uniformHemispherePdf", 0.0f);
}

Vec2 invertUniformHemisphere(const Vec3& w) {
    // TODO(01) The u in [0, 1)^2 that Eq. 1.9 maps to w (angles through turns()).
    (void)w;
    return PS_TODO("lesson 01: invertUniformHemisphere", Vec2(0.0f));
}

Vec2 sampleConcentricDisk(const Vec2& u) {
    // TODO(01) A point uniform per unit area in the unit disk by the concentric map (Eq. 1.10): all four wedges.
    (void)u;
    return PS_TODO("lesson 01: sampleConcentricDisk", Vec2(0.0f));
}

float concentricDiskPdf(const Vec2& p) {
    // TODO(01) Its density per unit area (Eq. 1.10), 0 outside the disk.
    (void)p;
    return PS_TODO("lesson 01: concentricDiskPdf", 0.0f);
}

Vec2 invertConcentricDisk(const Vec2& p) {
    // TODO(01) The u in [0, 1)^2 that Eq. 1.10 maps to p: the wedge follows from p's angle.
    (void)p;
    return PS_TODO("lesson 01: invertConcentricDisk", Vec2(0.0f));
}

Vec3 sampleCosineHemisphere(const Vec2& u) {
    // TODO(01) A unit direction with density cos(theta) / pi per solid angle (Eq. 1.11); clamp before sqrt (Pitfalls).
    (void)u;
    return PS_TODO("lesson 01: sampleCosineHemisphere", Vec3(0.0f, 0.0f, 1.0f));
}

float cosineHemispherePdf(const Vec3& w) {
    // TODO(01) Its density per unit solid angle (Eq. 1.11), 0 below the horizon.
    (void)w;
    return PS_TODO("lesson 01: cosineHemispherePdf", 0.0f);
}

Vec2 invertCosineHemisphere(const Vec3& w) {
    // TODO(01) The u in [0, 1)^2 that Eq. 1.11 maps to w.
    (void)w;
    return PS_TODO("lesson 01: invertCosineHemisphere", Vec2(0.0f));
}

Vec3 samplePhongLobe(const Vec2& u, float exponent) {
    // TODO(01) A unit direction around +z with Eq. 1.12's density per solid angle; finite for n up to 1e6 and never
    //          on the horizon (README, Pitfalls: "Float u is never 1").
    (void)u; (void)exponent;
    return PS_TODO("lesson 01: samplePhongLobe", Vec3(0.0f, 0.0f, 1.0f));
}

float phongLobePdf(const Vec3& w, float exponent) {
    // TODO(01) Eq. 1.12's density per unit solid angle, 0 below the horizon.
    (void)w; (void)exponent;
    return PS_TODO("lesson 01: phongLobePdf", 0.0f);
}

Vec2 invertPhongLobe(const Vec3& w, float exponent) {
    // TODO(01) The u in [0, 1)^2 that Eq. 1.12 maps to w.
    (void)w; (void)exponent;
    return PS_TODO("lesson 01: invertPhongLobe", Vec2(0.0f));
}

Vec2 sampleUniformTriangle(const Vec2& u) {
    // TODO(01) Barycentrics (b1, b2) uniform over the triangle (Eq. 1.13).
    (void)u;
    return PS_TODO("lesson 01: sampleUniformTriangle", Vec2(0.0f));
}

Vec2 invertUniformTriangle(const Vec2& b) {
    // TODO(01) The u that Eq. 1.13 maps to b; the corner b = (0, 0) gives u = (0, 0), not NaN.
    (void)b;
    return PS_TODO("lesson 01: invertUniformTriangle", Vec2(0.0f));
}

}  // namespace ps
