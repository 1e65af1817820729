// Lesson 11 — distributed ray tracing: lens, area lights and glossy lobes sampled, mirrors and
// glass followed, no diffuse interreflection. Interface: lessons/11-classics/distributed.h.
// Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/distributed.h"
#include "todo.h"

namespace ps {

Color LiDistributed(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    //! TODO(11) Eq. 11.19: follow the ray for bounces = 0, 1, ..., with the throughput beta (1 at
    //!          first). At each step, in this order:
    //!          1. the emission the ray finds (the hit surface's light, or scene.background where it
    //!             leaves): beta Le w, w = 1 after the camera or a delta bounce, else the power
    //!             heuristic of the BSDF sample's pdf against pdfLightDirection from the previous
    //!             point (as lesson 3's LiMIS). Stop at a miss or at bounces == maxDepth.
    //!          2. at a non-delta surface, a light sample (sampleDirectLight(scene, sp, wo,
    //!             uLight, uPoint), lesson 2; uLight = rng.uniform() drawn before uPoint =
    //!             rng.uniform2(), into variables): beta d.value w, with w = 1 at a
    //!             diffuse surface (no BSDF sample competes there) and the power heuristic of
    //!             d.pdfLight against d.pdfBSDF at a glossy one.
    //!          3. a diffuse surface ends the path (no diffuse interreflection).
    //!          4. glossy, mirror, glass: sampleBSDF(m, n, wo, u, uLobe, Transport::Radiance, b)
    //!             (u = rng.uniform2() before uLobe = rng.uniform(); stop if it fails), beta *=
    //!             b.weight, and go on from a ray spawned along b.wi.
    //!          Pitfalls: b.weight is f |cos| / pdf: the lobe's pdf alone is not the glossy
    //!          reflection; a light sample MIS-weighted at a diffuse point loses light.
    //! STUB (void)scene; (void)cameraRay; (void)rng; (void)maxDepth;
    //! STUB return PS_TODO("lesson 11: LiDistributed", Color(0.0f));
    //! BEGIN
    Color L(0.0f), beta(1.0f);
    Ray ray = cameraRay;
    bool delta = true;  // the camera ray, or a delta bounce: the emission found counts in full
    float pdfPrev = 0.0f;
    Vec3 pPrev;
    for (int bounces = 0;; ++bounces) {
        SurfacePoint sp;
        const bool hit = scene.intersect(ray, sp);
        const int light = hit ? sp.light : scene.background;
        if (light >= 0) {
            const Color Le =
                hit ? emittedRadiance(scene.lights[size_t(light)], sp.n, -ray.d) : scene.backgroundRadiance();
            const float w = delta ? 1.0f
                                  : misWeight(Heuristic::Power, 1.0f, pdfPrev, 1.0f,
                                              pdfLightDirection(scene, light, pPrev, sp.p, sp.n));
            L += beta * Le * w;
        }
        if (!hit || bounces == maxDepth) break;
        const Material& m = scene.materials[size_t(sp.material)];
        const Vec3 wo = -ray.d;
        if (!m.isDelta()) {
            // Named, in this order: C++ evaluates a call's arguments in no fixed order.
            const float uLight = rng.uniform();
            const Vec2 uPoint = rng.uniform2();
            const DirectSample d = sampleDirectLight(scene, sp, wo, uLight, uPoint);
            const float w =
                m.kind == BSDFKind::Diffuse ? 1.0f : misWeight(Heuristic::Power, 1.0f, d.pdfLight, 1.0f, d.pdfBSDF);
            L += beta * d.value * w;
        }
        if (m.kind == BSDFKind::Diffuse) break;
        // Named, in this order: C++ evaluates a call's arguments in no fixed order.
        const Vec2 u = rng.uniform2();  // in this order, as the light sample's numbers above
        const float uLobe = rng.uniform();
        BSDFSample b;
        if (!sampleBSDF(m, sp.n, wo, u, uLobe, Transport::Radiance, b)) break;
        beta *= b.weight;
        delta = b.delta;
        pdfPrev = b.pdf;
        pPrev = sp.p;
        ray = scene.spawnRay(sp, b.wi);
    }
    return L;
    //! END
}

}  // namespace ps
