// Lesson 3's path tracers: random walks from the camera that estimate the rendering equation's
// Neumann series (Eq. 3.2), with BSDF sampling only, with next-event estimation, and with
// next-event estimation and BSDF hits combined by MIS; Russian roulette ends long paths without
// bias. Implemented in solutions/03-path-tracing/*.cpp (reference) or
// assignments/03-path-tracing/*.cpp (yours); lessons/03-path-tracing/README.md derives every
// formula (Eq. 3.1-3.9). They use lesson 2's direct.h and mis.h.
//
// maxDepth is the largest number of bounces a path may have: 0 = only the emission seen
// directly, 1 = also light reflected once (direct illumination), and so on (Eq. 3.3).
#pragma once
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

// Radiance along the camera ray, estimated by a random walk that samples the BSDF at every
// vertex and adds the emission it happens to hit (Eq. 3.3, 3.4). Algorithm "pt-bsdf".
Color LiRandomWalk(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth);

// The same walk with next-event estimation: at every vertex a light sample (lesson 2's
// sampleDirectLight); emission hit by the walk counts only when seen directly or after a
// specular bounce (Eq. 3.6). Algorithm "pt-nee".
Color LiNextEvent(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth);

// Next-event estimation and BSDF hits combined by MIS with kPathHeuristic (Eq. 3.7). Algorithm "pt".
constexpr Heuristic kPathHeuristic = Heuristic::Power;
Color LiMIS(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth);

}  // namespace ps
