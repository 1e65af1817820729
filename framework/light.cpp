#include "light.h"
#include <algorithm>
#include "scene.h"

namespace ps {

namespace {

// Uniform point on an area light: pick a primitive by area, then a point on it.
void sampleAreaPoint(const Scene& scene, const Light& light, const Vec2& u, Vec3& p, Vec3& n) {
    // Reuse u.x for the primitive choice and, rescaled, for the point (keeps 2 dimensions).
    const size_t k = light.primByArea.sample(u.x);
    const float pmf = light.primByArea.pmf(k);
    double cdfLo = 0.0;
    for (size_t j = 0; j < k; ++j) cdfLo += light.primByArea.pmf(j);
    const float ux = glm::clamp(static_cast<float>((u.x - cdfLo) / pmf), 0.0f, 0x1.fffffep-1f);
    const Primitive& pr = scene.prims[light.prims[k]];
    if (pr.shape == ShapeKind::Triangle) {
        const Triangle& t = scene.triangles[pr.index];
        const Vec2 b = sampleUniformTriangle(Vec2(ux, u.y));
        p = (1.0f - b.x - b.y) * t.p0 + b.x * t.p1 + b.y * t.p2;
        n = t.normal();
    } else {
        const Sphere& s = scene.spheres[pr.index];
        n = sampleUniformSphere(Vec2(ux, u.y));
        p = s.center + s.radius * n;
    }
}

}  // namespace

Color emittedRadiance(const Light& light, const Vec3& n, const Vec3& w) {
    if (light.kind == LightKind::Background) return light.Le;
    if (light.kind != LightKind::Area) return Color(0.0f);
    return glm::dot(n, w) > 0.0f ? light.Le : Color(0.0f);
}

LightPdf pdfLight(const Scene& scene, int l) {
    const Light& light = scene.lights[l];
    LightPdf p;
    switch (light.kind) {
    case LightKind::Area: p.pdfA = light.area > 0.0f ? 1.0f / light.area : 0.0f; break;
    case LightKind::Point: p.pdfA = 1.0f; break;
    case LightKind::Background: p.pdfW = uniformSpherePdf(); break;
    }
    return p;
}

LightSample sampleLight(const Scene& scene, int l, const Vec3& ref, const Vec2& u) {
    const Light& light = scene.lights[l];
    LightSample s;
    switch (light.kind) {
    case LightKind::Area: {
        sampleAreaPoint(scene, light, u, s.p, s.n);
        const Vec3 d = s.p - ref;
        s.dist = glm::length(d);
        s.wi = d / s.dist;
        s.Le = emittedRadiance(light, s.n, -s.wi);
        s.pdfA = pdfLight(scene, l).pdfA;
        break;
    }
    case LightKind::Point: {
        s.p = light.position;
        const Vec3 d = s.p - ref;
        s.dist = glm::length(d);
        s.wi = d / s.dist;
        s.Le = light.Le;
        s.pdfA = pdfLight(scene, l).pdfA;
        break;
    }
    case LightKind::Background:
        s.wi = sampleUniformSphere(u);
        s.dist = kInf;
        s.Le = light.Le;
        s.pdfW = pdfLight(scene, l).pdfW;
        break;
    }
    return s;
}

EmissionSample sampleEmission(const Scene& scene, int l, const Vec2& uPos, const Vec2& uDir) {
    const Light& light = scene.lights[l];
    EmissionSample e;
    switch (light.kind) {
    case LightKind::Area: {
        sampleAreaPoint(scene, light, uPos, e.p, e.n);
        const Vec3 local = sampleCosineHemisphere(cosineWarpU(uDir));  // never the rim
        e.dir = Frame(e.n).toWorld(local);
        e.pdfA = pdfLight(scene, l).pdfA;
        e.pdfW = cosineHemispherePdf(local);
        e.Le = light.Le;
        break;
    }
    case LightKind::Point:
        e.p = light.position;
        e.dir = sampleUniformSphere(uDir);
        e.n = e.dir;
        e.pdfA = 1.0f;
        e.pdfW = uniformSpherePdf();
        e.Le = light.Le;
        break;
    case LightKind::Background: {
        // Direction into the scene, origin on the disk of radius R facing it, outside the
        // bounding sphere (pbrt's construction).
        e.dir = -sampleUniformSphere(uDir);
        const Frame f(e.dir);
        const float r = std::sqrt(uPos.x), phi = 2.0f * kPi * uPos.y;
        e.p = scene.center + scene.radius * (-e.dir + r * std::cos(phi) * f.s + r * std::sin(phi) * f.t);
        e.n = e.dir;
        e.pdfA = 1.0f / (kPi * scene.radius * scene.radius);
        e.pdfW = uniformSpherePdf();
        e.Le = light.Le;
        break;
    }
    }
    return e;
}

EmissionPdf pdfEmission(const Scene& scene, int l, const Vec3& n, const Vec3& dir) {
    const Light& light = scene.lights[l];
    EmissionPdf p;
    switch (light.kind) {
    case LightKind::Area:
        p.pdfA = pdfLight(scene, l).pdfA;
        p.pdfW = std::max(0.0f, glm::dot(n, dir)) * kInvPi;
        break;
    case LightKind::Point:
        p.pdfA = 1.0f;
        p.pdfW = uniformSpherePdf();
        break;
    case LightKind::Background:
        p.pdfA = 1.0f / (kPi * scene.radius * scene.radius);
        p.pdfW = pdfLight(scene, l).pdfW;
        break;
    }
    return p;
}

float lightPower(const Scene& scene, int l) {
    const Light& light = scene.lights[l];
    switch (light.kind) {
    case LightKind::Area: return kPi * light.area * luminance(light.Le);  // one-sided
    case LightKind::Point: return 4.0f * kPi * luminance(light.Le);
    case LightKind::Background: return 4.0f * kPi * kPi * scene.radius * scene.radius * luminance(light.Le);
    }
    return 0.0f;
}

}  // namespace ps
