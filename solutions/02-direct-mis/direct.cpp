// Lesson 2 — direct illumination: light sampling, BSDF sampling and their combination by
// multiple importance sampling. Interface: lessons/02-direct-mis/direct.h.
// Equation numbers refer to lessons/02-direct-mis/README.md.
#include "02-direct-mis/direct.h"
#include "todo.h"

namespace ps {

namespace {

// Shadow ray: does the surface point sp see the sampled light point? (Area lights: both ends
// offset off their surfaces; point lights: up to the position; background: nothing in the way
// all the way out of the scene.)
[[maybe_unused]] bool unoccluded(const Scene& scene, const SurfacePoint& sp, const LightSample& ls, LightKind kind) {
    switch (kind) {
    case LightKind::Area: {
        SurfacePoint onLight;
        onLight.p = ls.p;
        onLight.n = ls.n;
        onLight.errScale = maxAbsComponent(ls.p);
        return !scene.occluded(scene.spawnRayTo(sp, onLight));
    }
    case LightKind::Point: return !scene.occluded(scene.spawnRayTo(sp, ls.p));
    case LightKind::Background: return !scene.occluded(scene.spawnRay(sp, ls.wi));
    }
    return false;
}

}  // namespace

float pdfAToSolidAngle(float pdfA, float dist, float cosAtLight) {
    //! TODO(02) Convert the area pdf to solid angle: p_w = p_A dist^2 / cos (Eq. 2.3);
    //!          return 0 when cosAtLight <= 0.
    //! STUB (void)pdfA; (void)dist; (void)cosAtLight;
    //! STUB return PS_TODO("lesson 02: pdfAToSolidAngle", 0.0f);
    //! BEGIN
    if (!(cosAtLight > 0.0f)) return 0.0f;
    return pdfA * dist * dist / cosAtLight;
    //! END
}

float pdfLightDirection(const Scene& scene, int light, const Vec3& ref, const Vec3& p, const Vec3& n) {
    //! TODO(02) The pdf of the direction from ref to p under light sampling (Eq. 2.4): the
    //!          selection probability scene.lightSelectionProb(light) times
    //!            area light: pdfLight's area density converted by pdfAToSolidAngle, with the
    //!                        distance from ref to p and the cosine between n and the unit
    //!                        direction from p to ref;
    //!            background: pdfLight's solid-angle density;
    //!            point light: 0 (a delta light: no direction hits it by chance, Eq. 2.12).
    //! STUB (void)scene; (void)light; (void)ref; (void)p; (void)n;
    //! STUB return PS_TODO("lesson 02: pdfLightDirection", 0.0f);
    //! BEGIN
    const float select = scene.lightSelectionProb(light);
    switch (scene.lights[light].kind) {
    case LightKind::Area: {
        const Vec3 d = ref - p;
        const float dist = glm::length(d);
        if (!(dist > 0.0f)) return 0.0f;
        return select * pdfAToSolidAngle(pdfLight(scene, light).pdfA, dist, glm::dot(n, d / dist));
    }
    case LightKind::Background: return select * pdfLight(scene, light).pdfW;
    case LightKind::Point: return 0.0f;
    }
    return 0.0f;
    //! END
}

DirectSample sampleDirectLight(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, float uLight,
                               const Vec2& uPoint) {
    DirectSample d;
    //! TODO(02) Light sampling (Eq. 2.4):
    //!          1. l = scene.selectLight(uLight, select) (-1: no lights); ls = sampleLight(scene,
    //!             l, sp.p, uPoint); d.wi = ls.wi.
    //!          2. f = evalBSDF(material of sp, sp.n, wo, ls.wi), cos = |dot(sp.n, ls.wi)|.
    //!          3. The pdf of ls.wi per unit solid angle, times select (d.pdfLight):
    //!               area light: ls.pdfA is per unit area: convert it (Eq. 2.3) with ls.dist and
    //!                           the cosine at the light, dot(ls.n, -ls.wi);
    //!               background: ls.pdfW is already per solid angle;
    //!               point light: no density; d.pdfLight = select, d.delta = true, and ls.Le is
    //!                            an intensity: the value is f I cos / (select dist^2) (Eq. 2.4).
    //!          4. d.pdfBSDF = pdfBSDF(material, sp.n, wo, ls.wi) (0 for a point light, Eq. 2.12).
    //!          5. If f, ls.Le or the pdf is 0, return d with value 0 before tracing anything;
    //!             else if unoccluded(scene, sp, ls, kind) (above), d.value = f Le cos / pdf.
    //! STUB (void)scene; (void)sp; (void)wo; (void)uLight; (void)uPoint;
    //! STUB return PS_TODO("lesson 02: sampleDirectLight", d);
    //! BEGIN
    float select = 0.0f;
    const int l = scene.selectLight(uLight, select);
    if (l < 0 || !(select > 0.0f)) return d;
    const Light& light = scene.lights[l];
    const LightSample ls = sampleLight(scene, l, sp.p, uPoint);
    const Material& m = scene.materials[sp.material];
    d.wi = ls.wi;
    const Color f = evalBSDF(m, sp.n, wo, ls.wi);
    const float cosTheta = std::abs(glm::dot(sp.n, ls.wi));
    Color Le = ls.Le;
    switch (light.kind) {
    case LightKind::Area: d.pdfLight = select * pdfAToSolidAngle(ls.pdfA, ls.dist, glm::dot(ls.n, -ls.wi)); break;
    case LightKind::Background: d.pdfLight = select * ls.pdfW; break;
    case LightKind::Point:
        d.pdfLight = select;
        d.delta = true;
        Le /= ls.dist * ls.dist;  // irradiance I / d^2 at normal incidence
        break;
    }
    d.pdfBSDF = d.delta ? 0.0f : pdfBSDF(m, sp.n, wo, ls.wi);
    if (isBlack(f) || isBlack(Le) || !(d.pdfLight > 0.0f)) return d;
    if (!unoccluded(scene, sp, ls, light.kind)) return d;
    d.value = f * Le * (cosTheta / d.pdfLight);
    return d;
    //! END
}

DirectSample sampleDirectBSDF(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, const Vec2& u, float uLobe) {
    DirectSample d;
    //! TODO(02) BSDF sampling (Eq. 2.5):
    //!          1. sampleBSDF(material of sp, sp.n, wo, u, uLobe, Transport::Radiance, s); if it
    //!             fails return d. d.wi = s.wi, d.pdfBSDF = s.pdf, d.delta = s.delta.
    //!          2. Trace ray = scene.spawnRay(sp, s.wi) with scene.intersect(ray, hit).
    //!             No hit: the background's radiance (scene.backgroundRadiance(); black if the
    //!             scene has none); its light index is scene.background.
    //!             A hit with hit.light >= 0: emittedRadiance(scene.lights[hit.light], hit.n, -s.wi).
    //!             Anything else: no emission, return d.
    //!          3. d.pdfLight: 0 after a delta lobe (Eq. 2.12), else pdfLightDirection(scene,
    //!             light index, sp.p, hit.p, hit.n) (the background ignores the last two).
    //!          4. d.value = s.weight * Le (s.weight is already f |cos| / pdf).
    //! STUB (void)scene; (void)sp; (void)wo; (void)u; (void)uLobe;
    //! STUB return PS_TODO("lesson 02: sampleDirectBSDF", d);
    //! BEGIN
    BSDFSample s;
    if (!sampleBSDF(scene.materials[sp.material], sp.n, wo, u, uLobe, Transport::Radiance, s)) return d;
    d.wi = s.wi;
    d.pdfBSDF = s.pdf;
    d.delta = s.delta;
    Ray ray = scene.spawnRay(sp, s.wi);
    SurfacePoint hit;
    int light = -1;
    Color Le(0.0f);
    if (!scene.intersect(ray, hit)) {
        light = scene.background;
        Le = scene.backgroundRadiance();
    } else if (hit.light >= 0) {
        light = hit.light;
        Le = emittedRadiance(scene.lights[light], hit.n, -s.wi);
    }
    if (light < 0 || isBlack(Le)) return d;
    d.pdfLight = s.delta ? 0.0f : pdfLightDirection(scene, light, sp.p, hit.p, hit.n);
    d.value = s.weight * Le;
    return d;
    //! END
}

Color directMultiSample(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, Heuristic heuristic,
                        const DirectRandom& u) {
    //! TODO(02) Multi-sample MIS with one sample of each technique (Eq. 2.6, n_light = n_bsdf = 1):
    //!          a = sampleDirectLight(scene, sp, wo, u.uLight, u.uPoint),
    //!          b = sampleDirectBSDF(scene, sp, wo, u.uBSDF, u.uLobe);
    //!          return w_light(a) a.value + w_bsdf(b) b.value, each weight from misWeight (mis.h)
    //!          with the sample's own pdf against the other technique's pdf of the same direction.
    //! STUB (void)scene; (void)sp; (void)wo; (void)heuristic; (void)u;
    //! STUB return PS_TODO("lesson 02: directMultiSample", Color(0.0f));
    //! BEGIN
    const DirectSample a = sampleDirectLight(scene, sp, wo, u.uLight, u.uPoint);
    const DirectSample b = sampleDirectBSDF(scene, sp, wo, u.uBSDF, u.uLobe);
    return misWeight(heuristic, 1.0f, a.pdfLight, 1.0f, a.pdfBSDF) * a.value +
           misWeight(heuristic, 1.0f, b.pdfBSDF, 1.0f, b.pdfLight) * b.value;
    //! END
}

Color directOneSample(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, Heuristic heuristic,
                      const DirectRandom& u) {
    //! TODO(02) One-sample MIS (Eq. 2.11) with c = kOneSampleLightProbability: if u.uChoice < c,
    //!          a light sample a, returned as w_light(a) a.value / c; else a BSDF sample b,
    //!          returned as w_bsdf(b) b.value / (1 - c). The weights use the choice probabilities
    //!          as the n_i: misWeight(heuristic, c, ..., 1 - c, ...) for the light sample.
    //! STUB (void)scene; (void)sp; (void)wo; (void)heuristic; (void)u;
    //! STUB return PS_TODO("lesson 02: directOneSample", Color(0.0f));
    //! BEGIN
    const float c = kOneSampleLightProbability;
    if (u.uChoice < c) {
        const DirectSample a = sampleDirectLight(scene, sp, wo, u.uLight, u.uPoint);
        return a.value * (misWeight(heuristic, c, a.pdfLight, 1.0f - c, a.pdfBSDF) / c);
    }
    const DirectSample b = sampleDirectBSDF(scene, sp, wo, u.uBSDF, u.uLobe);
    return b.value * (misWeight(heuristic, 1.0f - c, b.pdfBSDF, c, b.pdfLight) / (1.0f - c));
    //! END
}

}  // namespace ps
