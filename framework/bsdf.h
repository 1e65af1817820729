// Materials and their BSDFs: Lambertian, normalized Phong, perfect mirror, smooth dielectric.
// Conventions: wo and wi point away from the surface, n is the unit geometric normal.
// Lambertian and Phong reflect on both sides of a surface; the dielectric uses n to tell
// outside (the side n points to, index 1) from inside (index ior).
#pragma once
#include <string>
#include "vecmath.h"

namespace ps {

enum class BSDFKind { Diffuse, Phong, Mirror, Dielectric };

// Which quantity flows along the path: radiance (paths built from the camera) or importance
// (paths built from the lights). Only refraction is non-symmetric (the eta^2 factor).
enum class Transport { Radiance, Importance };

struct Material {
    std::string name;
    BSDFKind kind = BSDFKind::Diffuse;
    Color albedo = Color(0.5f);  // diffuse / Phong / mirror reflectance
    float exponent = 0.0f;       // Phong exponent n >= 0
    float ior = 1.5f;            // dielectric: index of refraction inside / outside

    // Delta lobes cannot be evaluated or hit by chance: f and pdf of a given pair are 0, and
    // only sampleBSDF produces their directions. Handled as a flag, never as a huge pdf.
    bool isDelta() const { return kind == BSDFKind::Mirror || kind == BSDFKind::Dielectric; }
};

struct BSDFSample {
    Vec3 wi;             // sampled direction (unit, away from the surface)
    Color weight;        // f * |cos(theta_i)| / pdf (delta: the lobe's throughput)
    float pdf = 0.0f;    // solid-angle pdf; for a delta lobe the probability of choosing it
    bool delta = false;  // wi came from a delta lobe
};

// f(wo, wi) for non-delta materials (0 for delta ones and for wi on the wrong side).
// For Importance transport the arguments are swapped in meaning (adjoint BSDF); the
// materials here are symmetric except refraction, which is a delta lobe.
Color evalBSDF(const Material& m, const Vec3& n, const Vec3& wo, const Vec3& wi);

// Solid-angle pdf with which sampleBSDF produces wi (0 for delta materials).
float pdfBSDF(const Material& m, const Vec3& n, const Vec3& wo, const Vec3& wi);

// Samples wi given wo. u picks the direction, uLobe picks reflection/refraction.
// Returns false for an invalid sample (e.g. a Phong direction below the surface).
bool sampleBSDF(const Material& m, const Vec3& n, const Vec3& wo, const Vec2& u, float uLobe, Transport mode,
                BSDFSample& s);

// Fresnel reflectance of a smooth dielectric for unpolarised light; cosThetaI > 0 on the
// side with index etaI. Returns 1 under total internal reflection.
float fresnelDielectric(float cosThetaI, float etaI, float etaT);

}  // namespace ps
