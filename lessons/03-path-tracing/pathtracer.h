// Lesson 3's path tracers: one random walk from the camera (cameraWalk, walk.h) that estimates
// the rendering equation's Neumann series (Eq. 3.2), and three estimators that say what to add
// at each of its vertices: BSDF sampling only, with next-event estimation, and with next-event
// estimation and BSDF hits combined by MIS; Russian roulette ends long paths without bias.
// Implemented in solutions/03-path-tracing/*.cpp (reference) or assignments/03-path-tracing/*.cpp
// (yours); lessons/03-path-tracing/README.md derives every formula (Eq. 3.1-3.10). They use
// lesson 2's direct.h and mis.h.
//
// maxDepth is the largest number of bounces a path may have: 0 = only the emission seen
// directly, 1 = also light reflected once (direct illumination), and so on (Eq. 3.3).
#pragma once
#include "02-direct-mis/direct.h"
#include "03-path-tracing/walk.h"
#include "integrator.h"

namespace ps {

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

// The two halves of what vertex v contributes under MIS (Eq. 3.7), each times v.beta:
// the emission the walk found there (the surface's, or the background's where the walk left the
// scene), MIS-weighted against the light sample that could have found it at the previous vertex;
Color misEmission(const Scene& scene, const WalkVertex& v);
// and one light sample taken there (its numbers from rng), MIS-weighted against the walk's own
// density of its direction (pdfWalk); black where none is taken (a miss, a delta material, the
// vertex with maxDepth bounces).
Color misLightSample(const Scene& scene, const WalkVertex& v, Rng& rng, int maxDepth);
// LiMIS's visitor: adds both to L, the emission first (plumbing). LiMIS is cameraWalk with it;
// every walk that estimates radiance as pt does uses it too.
void addMISContribution(const Scene& scene, const WalkVertex& v, Rng& rng, int maxDepth, Color& L);

// The density with which the walk would have left v in the direction of the light sample d: 0
// for a delta light (nothing else samples it, Eq. 2.12), else pdfWalk: d.pdfBSDF unless the walk
// has its own direction sampler (plumbing, path_integrators.cpp).
float pdfWalk(const Scene& scene, const WalkVertex& v, const DirectSample& d);

}  // namespace ps
