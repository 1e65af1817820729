// The simplest integrators: what the first hit looks like. They exercise the whole renderer
// (camera, BVH, materials, film) without any light transport.
#pragma once
#include "integrator.h"

namespace ps {

// Radiance = reflectance * |cos| between the normal and the eye ray at the first hit;
// emitters show their emission, rays that leave show the background.
class EyeLight : public PixelIntegrator {
public:
    Color Li(const Scene& scene, const Ray& ray, Rng& rng) const override;
};

// The normal at the first hit as a colour (n + 1) / 2; black where the ray leaves.
class NormalView : public PixelIntegrator {
public:
    Color Li(const Scene& scene, const Ray& ray, Rng& rng) const override;
};

}  // namespace ps
