// Lesson 4's measurements: what a pixel (or any sensor) records, written as the inner product
// <W_e, L> of the sensor's emitted importance and the radiance arriving at it (Eq. 4.1), and the
// same measurement seen from the lights, <L_e, W> (Eq. 4.11). Implemented in
// solutions/04-measurement/*.cpp (reference) or assignments/04-measurement/*.cpp (yours);
// lessons/04-measurement/README.md derives every formula (Eq. 4.1-4.15).
//
// This lesson's pieces:
//   Camera::We (framework/camera.h)   the pinhole's emitted importance, over the whole image (4.5)
//   pixelImportance                   one pixel's sensor W_e^(j) (4.6)
//   pixelMeasurementSample            one sample of <W_e^(j), L> for a given direction (4.7)
//   fluxParticle                      one particle of the flux through a region S (4.12, 4.13)
#pragma once
#include <string>
#include <vector>
#include "03-path-tracing/pathtracer.h"
#include "integrator.h"

namespace ps {

// The sensor of pixel (px, py) (Eq. 4.6): W_e^(j)(dir) = width * height * W_e(dir) for the
// directions dir (unit, leaving the pinhole) whose raster position lies in that pixel, 0 for
// every other direction. Normalised so that the pixel measures the average radiance over its
// area on the image plane (Eq. 4.4): the integral of W_e^(j) cos(theta) over the pixel's
// directions is 1.
float pixelImportance(const Camera& camera, int px, int py, const Vec3& dir);

// One sample of pixel (px, py)'s measurement I_j = <W_e^(j), L> (Eq. 4.7) for a direction dir
// drawn by the caller with solid-angle density pdf (> 0): W_e^(j)(dir) L(dir) cos(theta) / pdf,
// where L is the radiance arriving at the pinhole from dir, estimated by lesson 3's path tracer
// LiMIS with at most maxDepth bounces and cos(theta) is taken against the camera's forward
// axis. 0 without tracing anything when W_e^(j)(dir) is 0.
Color pixelMeasurementSample(const Scene& scene, int px, int py, const Vec3& dir, float pdf, Rng& rng, int maxDepth);

// A region S of the scene's surfaces (the second sensor of this lesson): a set of primitives.
struct Region {
    std::vector<bool> member;  // per primitive of the scene: part of S?
    double area = 0.0;         // total area of S
    bool contains(uint32_t prim) const { return prim < member.size() && member[prim]; }
};
// The region made of every primitive with the given material; throws InputError if there is none.
Region regionWithMaterial(const Scene& scene, const std::string& material);

// The start of a particle on light l (lessons 4, 5, 7): the point sampleEmission chose, as a
// SurfacePoint that rays can leave from (Scene::spawnRay, spawnRayTo). A point light's has
// errScale 0 (no offset: the point is not on a surface).
SurfacePoint emissionPoint(const Scene& scene, int l, const EmissionSample& e);

// One particle of the flux through S, measured from the lights (Eq. 4.12, 4.13): choose a light
// by power (scene.selectLight(rng.uniform(), P)), a point and direction on it
// (sampleEmission(scene, l, uPos, uDir), uPos = rng.uniform2() drawn before uDir = rng.uniform2()),
// give the particle the power it carries, trace its ray, and return that power if the first
// surface it hits belongs to S (from either side), else 0. The mean over many particles is the
// flux through S of the light that reaches S straight from the lights (the only light in a scene
// where nothing else reflects).
Color fluxParticle(const Scene& scene, const Region& S, Rng& rng);

}  // namespace ps
