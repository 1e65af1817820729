// Lesson 2's direct illumination: light arriving at a surface point straight from the lights,
// estimated by sampling the lights, by sampling the BSDF, and by combining both with multiple
// importance sampling. Implemented in solutions/02-direct-mis/direct.cpp (reference) or
// assignments/02-direct-mis/direct.cpp (yours); lessons/02-direct-mis/README.md derives every
// formula (Eq. 2.1-2.12). Lesson 3's path tracers call these functions at every bounce.
#pragma once
#include "02-direct-mis/mis.h"
#include "scene.h"

namespace ps {

// A pdf per unit area at a point y of a light, seen from a reference point x at distance dist,
// converted to a pdf per unit solid angle of the direction from x to y (Eq. 2.3). cosAtLight is
// the cosine between the light's normal at y and the direction from y back to x; 0 when it is
// <= 0 (the light is seen edge-on or from behind: it sends nothing that way).
float pdfAToSolidAngle(float pdfA, float dist, float cosAtLight);

// The solid-angle pdf with which sampleDirectLight picks the point p (normal n) of light
// `light` from the reference point ref: the probability of choosing that light times the
// pdf of the point, converted to solid angle (Eq. 2.3, 2.4). Background: the selection
// probability times its direction pdf (p and n unused). Point lights: 0 (no direction can hit
// them by chance). MIS needs it when a BSDF sample hits an emitter.
float pdfLightDirection(const Scene& scene, int light, const Vec3& ref, const Vec3& p, const Vec3& n);

// One sample of the direct illumination at a surface point, taken by one technique.
struct DirectSample {
    Color value = Color(0.0f);  // f * Le * |cos theta| / pdf: the technique's own estimate
                                // (Eq. 2.4 or 2.5), unweighted; 0 if the sample is invalid,
                                // blocked or sees no emitter
    Vec3 wi = Vec3(0.0f);       // the direction from the surface point towards the light
    float pdfLight = 0.0f;      // pdf of wi under light sampling (incl. the light's selection
                                // probability); for a point light its selection probability
    float pdfBSDF = 0.0f;       // pdf of wi under BSDF sampling; for a delta lobe the
                                // probability of choosing it
    bool delta = false;         // the sample came from a delta distribution (a point light or
                                // a specular lobe): the other technique cannot produce it, its
                                // pdf above is 0 and the MIS weight of this sample is 1 (Eq. 2.12)
};

// Light sampling (Eq. 2.4): choose a light by power with uLight, a point on it with uPoint,
// and return the contribution of that point to the light leaving sp towards wo.
DirectSample sampleDirectLight(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, float uLight,
                               const Vec2& uPoint);

// BSDF sampling (Eq. 2.5): sample a direction from the BSDF at sp with (u, uLobe), trace it,
// and return the emission it finds (an area light's front side, or the background where the
// ray leaves the scene) times the sample's weight f |cos| / pdf.
DirectSample sampleDirectBSDF(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, const Vec2& u, float uLobe);

// The random numbers one direct-illumination estimate uses, drawn by the integrator in a fixed
// order, so that every estimator sees the same light sample for the same pixel and iteration.
struct DirectRandom {
    float uLight = 0.0f;       // which light
    Vec2 uPoint = Vec2(0.0f);  // where on it
    Vec2 uBSDF = Vec2(0.0f);   // which direction from the BSDF
    float uLobe = 0.0f;        // which lobe (reflection or refraction)
    float uChoice = 0.0f;      // one-sample MIS: which technique
};

// Multi-sample MIS (Eq. 2.6): one light sample and one BSDF sample, each weighted by the
// heuristic against the other technique.
Color directMultiSample(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, Heuristic heuristic,
                        const DirectRandom& u);

// One-sample MIS (Eq. 2.11): light sampling with probability kOneSampleLightProbability, else
// BSDF sampling; one sample, weighted by the heuristic with the choice probabilities as n_i.
constexpr float kOneSampleLightProbability = 0.5f;
Color directOneSample(const Scene& scene, const SurfacePoint& sp, const Vec3& wo, Heuristic heuristic,
                      const DirectRandom& u);

}  // namespace ps
