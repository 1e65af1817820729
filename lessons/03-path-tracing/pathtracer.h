// Lesson 3's path tracers: one random walk from the camera (cameraWalk) that estimates the
// rendering equation's Neumann series (Eq. 3.2), and three estimators that say what to add at
// each of its vertices: BSDF sampling only, with next-event estimation, and with next-event
// estimation and BSDF hits combined by MIS; Russian roulette ends long paths without bias. Implemented in solutions/03-path-tracing/*.cpp (reference) or
// assignments/03-path-tracing/*.cpp (yours); lessons/03-path-tracing/README.md derives every
// formula (Eq. 3.1-3.9). They use lesson 2's direct.h and mis.h.
//
// maxDepth is the largest number of bounces a path may have: 0 = only the emission seen
// directly, 1 = also light reflected once (direct illumination), and so on (Eq. 3.3).
#pragma once
#include <functional>
#include "02-direct-mis/direct.h"
#include "integrator.h"

namespace ps {

// Russian roulette (Eq. 3.5): never before a path has made kRouletteStartBounces bounces; from
// then on it survives each bounce with probability min(1, max component of its throughput),
// but never less than kRouletteMinSurvival (a path that survives is divided by the
// probability: a floor keeps that factor <= 20).
constexpr int kRouletteStartBounces = 3;
constexpr float kRouletteMinSurvival = 0.05f;

// The probability that a path with throughput beta, after `bounces` bounces, goes on (Eq. 3.5).
float survivalProbability(const Color& beta, int bounces);

// One vertex x_k of the camera walk, as the walk shows it to its visitor.
struct WalkVertex {
    int bounces = 0;       // k, the bounces made before reaching it: 0 = the camera ray's hit (Eq. 3.3)
    bool hit = false;      // false: the ray left the scene (sp is not set); the walk ends here
    SurfacePoint sp;       // the surface point hit
    Vec3 wo;               // unit, back along the ray that arrived (-ray.d): omega_o,k of Eq. 3.4
    Color beta;            // the throughput beta_k of the path up to here (Eq. 3.4), divided by
                           // every survival probability so far (Eq. 3.5)
    bool specular = true;  // the bounce into this vertex was a delta sample (BSDFSample::delta);
                           // true at bounces 0 (the camera ray)
    float pdfPrev = 0.0f;  // solid-angle pdf of the BSDF sample that led here (0 at bounces 0)
    Vec3 pPrev;            // the previous vertex's position sp.p (bounces >= 1)
};

// What to do at a vertex; return false to end the walk there. The walk calls it between the
// intersection and the BSDF sample, so it may draw numbers from the walk's rng (a light sample).
using WalkVisitor = std::function<bool(const WalkVertex&)>;

// The random walk from the camera (Eq. 3.3-3.5): follows `ray`, calls visit at every vertex
// x_0, x_1, ... in order (the escape included: a vertex with hit = false), and after x_k
// samples the BSDF (Transport::Radiance) and plays Russian roulette with
// survivalProbability(beta, k + 1). It ends after the visitor says so, after a miss, at
// bounces == maxDepth, or when the BSDF sample fails, is black or the roulette says stop.
// Lesson 7's camera subpath is this walk too.
void cameraWalk(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth, const WalkVisitor& visit);

// Radiance along the camera ray, estimated by the walk: it adds the emission of every vertex it
// happens to hit (Eq. 3.3, 3.4). Algorithm "pt-bsdf".
Color LiRandomWalk(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth);

// The walk with next-event estimation: at every vertex a light sample (lesson 2's
// sampleDirectLight); emission hit by the walk counts only when seen directly or after a
// specular bounce (Eq. 3.6). Algorithm "pt-nee".
Color LiNextEvent(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth);

// Next-event estimation and BSDF hits combined by MIS with kPathHeuristic (Eq. 3.7). Algorithm "pt".
constexpr Heuristic kPathHeuristic = Heuristic::Power;
Color LiMIS(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth);
// LiMIS's visitor: adds to L what vertex v contributes (Eq. 3.7), first the MIS-weighted emission
// the walk found there, then the MIS-weighted light sample taken there (its numbers from rng).
// LiMIS is cameraWalk with this visitor; lesson 10's walk with splitting uses it too.
void addMISContribution(const Scene& scene, const WalkVertex& v, Rng& rng, int maxDepth, Color& L);

}  // namespace ps
