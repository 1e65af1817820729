// Lesson 1's warps, used by the framework's materials and lights: each maps u in [0,1)^2 to
// a point or direction, with the pdf of the result and (where it exists) the inverse map.
// Directions are in local coordinates: z is the axis (the normal, or the Phong lobe's axis).
// Implemented in solutions/01-monte-carlo/warps.cpp (reference) or
// assignments/01-monte-carlo/warps.cpp (yours); lessons/01-monte-carlo/README.md derives them.
#pragma once
#include "vecmath.h"

namespace ps {

// Uniform on the unit sphere; pdf per unit solid angle (Eq. 1.8).
Vec3 sampleUniformSphere(const Vec2& u);
float uniformSpherePdf();
Vec2 invertUniformSphere(const Vec3& w);

// Uniform on the hemisphere z > 0 (Eq. 1.9).
Vec3 sampleUniformHemisphere(const Vec2& u);
float uniformHemispherePdf(const Vec3& w);
Vec2 invertUniformHemisphere(const Vec3& w);

// Concentric map of the square to the unit disk (Shirley & Chiu); pdf per unit area (Eq. 1.10).
Vec2 sampleConcentricDisk(const Vec2& u);
float concentricDiskPdf(const Vec2& p);
Vec2 invertConcentricDisk(const Vec2& p);

// Cosine-weighted hemisphere by Malley's method: pdf = cos(theta) / pi (Eq. 1.11).
Vec3 sampleCosineHemisphere(const Vec2& u);
float cosineHemispherePdf(const Vec3& w);
Vec2 invertCosineHemisphere(const Vec3& w);

// Phong lobe about +z: pdf = (n + 1) / (2 pi) cos^n(alpha), n >= 0 (Eq. 1.12).
Vec3 samplePhongLobe(const Vec2& u, float exponent);
float phongLobePdf(const Vec3& w, float exponent);
Vec2 invertPhongLobe(const Vec3& w, float exponent);

// Uniform on a triangle: the barycentric weights (b1, b2) of its second and third corners;
// pdf = 1 / area per unit area, i.e. 2 over the barycentric domain (Eq. 1.13).
Vec2 sampleUniformTriangle(const Vec2& u);
Vec2 invertUniformTriangle(const Vec2& b);

}  // namespace ps
