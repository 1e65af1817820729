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
    // TODO(02) The density per unit solid angle of a point sampled with pdfA per unit area (Eq. 2.3); 0 if the light
    //          faces away.
    (void)pdfA; (void)dist; (void)cosAtLight;
    return PS_TODO("lesson 02: pdfAToSolidAngle", 0.0f);
}

float pdfLightDirection(const Scene& scene, int light, const Vec3& ref, const Vec3& p, const Vec3& n) {
    // TODO(02) The light-sampling density per unit solid angle of the direction ref -> p, selection probability
    //          included (Eq. 2.3, 2.4; direct.h); 0 for a point light (Eq. 2.12). Pitfall: the sign of the cosine at
    //          the light (README 6).
    (void)scene; (void)light; (void)ref; (void)p; (void)n;
    return PS_TODO("lesson 02: pdfLightDirection", 0.0f);
}

DirectSample sampleDirectLight(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, float uLight,
                               const Vec2& uPoint) {
    DirectSample d;
    // TODO(02) One light sample of L_d (Eq. 2.4), every field as DirectSample documents it (direct.h); LightSample's
    //          densities and a point light's Le are described in framework/light.h. Pitfalls (README 6): the selection
    //          probability belongs to the density; mixed measures; a shadow ray that does not go through unoccluded(),
    //          or is traced for a zero value.
    (void)scene; (void)sp; (void)wo; (void)uLight; (void)uPoint;
    return PS_TODO("lesson 02: sampleDirectLight", d);
}

DirectSample sampleDirectBSDF(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, const Vec2& u, float uLobe) {
    DirectSample d;
    // TODO(02) One BSDF sample of L_d (Eq. 2.5) as DirectSample documents it; BSDFSample::weight: framework/bsdf.h.
    //          Emission comes from an emitter hit or, on a miss, the background (Scene::background). Pitfall: pdfLight
    //          is the light density of the point this ray hit, 0 after a delta lobe (Eq. 2.12).
    (void)scene; (void)sp; (void)wo; (void)u; (void)uLobe;
    return PS_TODO("lesson 02: sampleDirectBSDF", d);
}

Color directMultiSample(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, Heuristic heuristic,
                        const DirectRandom& u) {
    // TODO(02) L_d from one light and one BSDF sample combined by Eq. 2.6 (misWeight, mis.h). Pitfall: each weight
    //          compares the sample's own density with the other technique's density of the same direction.
    (void)scene; (void)sp; (void)wo; (void)heuristic; (void)u;
    return PS_TODO("lesson 02: directMultiSample", Color(0.0f));
}

Color directOneSample(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, Heuristic heuristic,
                      const DirectRandom& u) {
    // TODO(02) L_d from one technique chosen with probability c = kOneSampleLightProbability (Eq. 2.11). Pitfall:
    //          divide by the choice probability and use it as the n_i of the weights.
    (void)scene; (void)sp; (void)wo; (void)heuristic; (void)u;
    return PS_TODO("lesson 02: directOneSample", Color(0.0f));
}

}  // namespace ps
