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
    //! TODO(02) The density per unit solid angle of a point sampled with pdfA per unit area (Eq. 2.3); 0 if the light
    //!          faces away.
    //! STUB (void)pdfA; (void)dist; (void)cosAtLight;
    //! STUB return PS_TODO("lesson 02: pdfAToSolidAngle", 0.0f);
    //! BEGIN
    if (!(cosAtLight > 0.0f)) return 0.0f;
    return pdfA * dist * dist / cosAtLight;
    //! END
}

float pdfLightDirection(const Scene& scene, int light, const Vec3& ref, const Vec3& p, const Vec3& n) {
    //! TODO(02) The light-sampling density per unit solid angle of the direction ref -> p, selection probability
    //!          included (Eq. 2.3, 2.4; direct.h); 0 for a point light (Eq. 2.12). Pitfall: the sign of the cosine at
    //!          the light (README 6).
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
    //! TODO(02) One light sample of L_d (Eq. 2.4), every field as DirectSample documents it (direct.h); LightSample's
    //!          densities and a point light's Le are described in framework/light.h. Pitfalls (README 6): the selection
    //!          probability belongs to the density; mixed measures; a shadow ray that does not go through unoccluded(),
    //!          or is traced for a zero value.
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
    //! TODO(02) One BSDF sample of L_d (Eq. 2.5) as DirectSample documents it; BSDFSample::weight: framework/bsdf.h.
    //!          Emission comes from an emitter hit or, on a miss, the background (Scene::background). Pitfall: pdfLight
    //!          is the light density of the point this ray hit, 0 after a delta lobe (Eq. 2.12).
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
    //! TODO(02) L_d from one light and one BSDF sample combined by Eq. 2.6 (misWeight, mis.h). Pitfall: each weight
    //!          compares the sample's own density with the other technique's density of the same direction.
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
    //! TODO(02) L_d from one technique chosen with probability c = kOneSampleLightProbability (Eq. 2.11). Pitfall:
    //!          divide by the choice probability and use it as the n_i of the weights.
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
