// Lesson 6 — plumbing (nothing to write here): path vertices from what the framework gives,
// visibility and directions between vertices, and the Dirac delta of a specular vertex
// (Eq. 6.11). Interface: lessons/06-path-space/paths.h.
#include "06-path-space/paths.h"

namespace ps {

PathVertex surfaceVertex(const Scene& scene, const SurfacePoint& sp) {
    PathVertex v;
    v.sp = sp;
    v.onLight = sp.light >= 0;
    v.specular = sp.material >= 0 && scene.materials[size_t(sp.material)].isDelta();
    return v;
}

PathVertex lightVertex(const Scene& scene, int l, const EmissionSample& e) {
    const Light& light = scene.lights[size_t(l)];
    if (light.isInfinite()) {
        PathVertex v = backgroundVertex(scene, -e.dir);
        return v;
    }
    PathVertex v;
    v.sp = emissionPoint(scene, l, e);
    v.onLight = true;
    v.pointLight = light.isDelta();
    return v;
}

PathVertex lightVertex(const Scene& scene, int l, const LightSample& ls) {
    const Light& light = scene.lights[size_t(l)];
    if (light.isInfinite()) return backgroundVertex(scene, ls.wi);
    PathVertex v;
    v.sp.p = ls.p;
    v.sp.n = ls.n;
    v.sp.errScale = maxAbsComponent(ls.p);
    v.sp.light = l;
    v.onLight = true;
    v.pointLight = light.isDelta();
    return v;
}

PathVertex backgroundVertex(const Scene& scene, const Vec3& towardsBackground) {
    PathVertex v;
    v.sp.n = towardsBackground;
    v.sp.light = scene.background;
    v.onLight = true;
    v.infinite = true;
    return v;
}

PathVertex cameraVertex(const Scene& scene) {
    PathVertex v;
    v.sp.p = scene.camera.position();
    v.sp.n = scene.camera.forward();
    v.pinhole = true;
    return v;
}

PathVertex cameraVertex(const Scene& scene, const Vec3& z) {
    if (scene.camera.isPinhole()) return cameraVertex(scene);
    PathVertex v;
    v.sp.p = z;
    v.sp.n = scene.camera.forward();
    v.onCamera = true;
    return v;
}

bool visible(const Scene& scene, const PathVertex& a, const PathVertex& b) {
    if (a.infinite && b.infinite) return false;
    if (a.infinite || b.infinite) {
        const PathVertex& f = a.infinite ? b : a;
        const Vec3 d = a.infinite ? a.sp.n : b.sp.n;
        // A pinhole or a point light has errScale 0 (no offset), unless the light lies on a
        // surface: then the framework offsets the ray off it (Scene::spawnRay).
        const Ray r = scene.spawnRay(f.sp, d);
        return !scene.occluded(r);
    }
    if (a.deltaPosition() && b.deltaPosition()) {
        // The point light and the pinhole: spawnRayTo offsets neither (errScale 0), except a
        // point light that lies on a surface, which it moves off that surface.
        return glm::length(b.sp.p - a.sp.p) > 0.0f && !scene.occluded(scene.spawnRayTo(a.sp, b.sp.p));
    }
    // A camera model's point is no surface of the scene either: no offset at it.
    if (b.deltaPosition() || b.onCamera) return !scene.occluded(scene.spawnRayTo(a.sp, b.sp.p));
    if (a.deltaPosition() || a.onCamera) return !scene.occluded(scene.spawnRayTo(b.sp, a.sp.p));
    return !scene.occluded(scene.spawnRayTo(a.sp, b.sp));
}

float deltaTolerance(const PathVertex& a, const PathVertex& v, const PathVertex& b) {
    float far = maxAbsComponent(v.sp.p), shortest = kInf;
    for (const PathVertex* u : {&a, &b}) {
        if (u->infinite) continue;
        far = std::max(far, maxAbsComponent(u->sp.p));
        shortest = std::min(shortest, glm::length(u->sp.p - v.sp.p));
    }
    if (!(shortest > 0.0f) || shortest == kInf) return kDeltaTolerance;
    const float step = std::nextafter(far, kInf) - far;
    return std::max(kDeltaTolerance, 256.0f * step / shortest);
}

DeltaLobe deltaLobe(const Material& m, const Vec3& n, const Vec3& wLight, const Vec3& wCamera, float tolerance) {
    DeltaLobe d;
    const float cosL = glm::dot(n, wLight), cosC = glm::dot(n, wCamera);
    if (!m.isDelta() || cosL == 0.0f || cosC == 0.0f) return d;
    const float kTolerance = tolerance;
    const bool sameSide = (cosL > 0.0f) == (cosC > 0.0f);
    const Vec3 ns = cosL > 0.0f ? n : -n;
    // The numbers of the lobe the two sides select (reflection on one side, refraction across);
    // valid only if wCamera is that lobe's direction to the tolerance.
    if (m.kind == BSDFKind::Mirror) {
        if (!sameSide) return d;
        d.valid = glm::length(reflect(wLight, ns) - wCamera) <= kTolerance;
        d.fs = m.albedo / std::abs(cosC);
        d.pdfLight = d.pdfCamera = 1.0f;
        return d;
    }
    // Smooth dielectric: index 1 on the side n points to, m.ior on the other.
    const float etaL = cosL > 0.0f ? 1.0f : m.ior, etaC = cosC > 0.0f ? 1.0f : m.ior;
    const float aL = std::abs(cosL), aC = std::abs(cosC);
    if (sameSide) {
        const float etaOther = cosL > 0.0f ? m.ior : 1.0f;
        const float F = fresnelDielectric(aL, etaL, etaOther);
        d.valid = glm::length(reflect(wLight, ns) - wCamera) <= kTolerance;
        d.fs = Color(F / aC);
        d.pdfLight = F;
        d.pdfCamera = fresnelDielectric(aC, etaL, etaOther);  // the same side: the same F
        return d;
    }
    const float eta = etaL / etaC;
    const float sin2T = eta * eta * (1.0f - aL * aL);
    if (sin2T >= 1.0f) return d;  // total internal reflection: no refracted direction
    const float cosT = std::sqrt(1.0f - sin2T);
    const Vec3 t = glm::normalize(-eta * wLight + (eta * aL - cosT) * ns);
    const float FL = fresnelDielectric(aL, etaL, etaC), FC = fresnelDielectric(aC, etaC, etaL);
    d.valid = glm::length(t - wCamera) <= kTolerance;
    d.refracted = true;
    d.fs = Color((1.0f - FL) / aC);
    d.pdfLight = 1.0f - FL;
    d.pdfCamera = (1.0f - FC) * (etaL * etaL * aL) / (etaC * etaC * aC);
    return d;
}

}  // namespace ps
