// Lesson 11's distributed ray tracing (Cook, Porter and Carpenter 1984), as a special case of the
// path tracer (Eq. 11.19): rays distributed over the lens (depth of field: the framework's pixel
// loop, lessons/11-classics/thinlens.h), over the area lights (soft shadows: lesson 2's light
// sample), over the glossy lobe (glossy reflection: the Phong lobe sampled, lesson 1), and
// perfect mirror and glass recursion; no diffuse interreflection. Implemented in
// solutions/11-classics/distributed.cpp (reference) or assignments/11-classics/distributed.cpp
// (yours); lessons/11-classics/README.md derives it. Algorithm `drt` (distributed_integrator.cpp).
//
// The paths it carries, in Heckbert's notation (D Lambertian, G glossy = Phong, S specular =
// mirror or glass): L D? (G|S)* E with at most maxDepth bounces. A camera ray goes on through G
// and S vertices only; at every D or G vertex a light sample adds the L D and L G ends; an emitter
// the walk hits adds the L (G|S)* E paths and, after a G bounce, the L G ends too. Those two (the
// light sample at a G vertex and the G ray that hits the light) are one path sampled twice: both
// are weighted by the power heuristic (lesson 2, Eq. 2.8), as in lesson 3's pt. At a D vertex the
// light sample is the only technique: weight 1.
#pragma once
#include "03-path-tracing/pathtracer.h"

namespace ps {

// Eq. 11.19 as a path expression (framework/path_expression.h): what `drt` says it carries
// (Integrator::carriedPaths), and what `pt --paths` renders as its reference.
inline constexpr const char* kDistributedPaths = "LD?(G|S)*E";

// Radiance along the camera ray by distributed ray tracing (Eq. 11.19); maxDepth bounces at most.
Color LiDistributed(const Scene& scene, const Ray& ray, Rng& rng, int maxDepth);

}  // namespace ps
