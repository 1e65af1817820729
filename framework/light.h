// Lights: area lights (emissive triangles or spheres, one-sided on the normal's side for
// triangles, outward for spheres), point lights (a delta position) and a constant background.
#pragma once
#include <vector>
#include "vecmath.h"
#include "sampling.h"

namespace ps {

class Scene;

enum class LightKind { Area, Point, Background };

struct Light {
    LightKind kind = LightKind::Area;
    Color Le = Color(0.0f);       // area, background: radiance; point: intensity (W/sr)
    Vec3 position;                // point light
    std::vector<uint32_t> prims;  // area light: its primitives (indices into Scene::prims)
    Distribution1D primByArea;    // area light: picks a primitive proportionally to its area
    float area = 0.0f;            // area light: total area
    int line = 0;                 // the scene file's line that made it (0: not from a file)
    // Point light lying on surfaces (within 2^-17 of its coordinates' magnitude, Scene::finalize):
    // surfaceScale > 0, and surfacePlanes holds the normals of the distinct planes it lies in
    // (one on a face, two on an edge, three in a box's corner; planes within 1 degree of each other
    // count as one). Rays leaving it, and shadow rays ending at it, start off every one of those
    // planes on the side they go to (lightRayPoint; Scene::spawnRay, spawnRayTo): no ray hits
    // them at t = 0, they get none of its light, and each region between them gets the light
    // that goes into it. surfaceNormal is their mean (the offset where no such point is found).
    std::vector<Vec3> surfacePlanes;
    Vec3 surfaceNormal = Vec3(0.0f);
    float surfaceScale = 0.0f;


    bool isDelta() const { return kind == LightKind::Point; }  // a flag, not a huge pdf
    // At most this many distinct planes through a point light (a mesh vertex where more faces
    // at different angles meet refuses it: Scene::finalize).
    static constexpr size_t kMaxSurfacePlanes = 8;
    bool isInfinite() const { return kind == LightKind::Background; }
};

// Where a ray leaving a point light that lies on surfaces in direction w starts (or a shadow ray
// to it from direction -w ends): its position moved off each plane of light.surfacePlanes to the
// side w goes to, by at least 2^-16 of the light's surfaceScale-given magnitude from each (the
// shortest such move: one plane, along its normal; an edge or a corner, the point nearest the
// light in the region w enters). Its position itself for a light on no surface.
Vec3 lightRayPoint(const Light& light, const Vec3& w);
// Whether x lies in one of the planes of a point light on surfaces (within the 2^-17 of its
// coordinates' magnitude that put the light on them): such a point gets none of its light.
bool inLightPlane(const Light& light, const Vec3& x);

// A point on a light, sampled for a reference point ref (next-event estimation), with the
// densities it was sampled with, each in its own measure (the other one 0):
struct LightSample {
    Vec3 p;             // point on the light (point light: its position; background: unused)
    Vec3 n;             // normal at p (area lights)
    Vec3 wi;            // unit direction from ref towards the light
    float dist = kInf;  // distance from ref to p (background: infinite)
    Color Le;           // radiance leaving p towards ref; point light: intensity
    float pdfA = 0.0f;  // per unit AREA at p: an area light's (uniform by area); a point light's 1,
                        // the coefficient of its delta position; 0 for the background (no point)
    float pdfW = 0.0f;  // per unit SOLID ANGLE of wi: the background's; 0 for the others (theirs
                        // is pdfA, converted at ref)
};

// Samples a point on light `l` for the reference point ref; u uniform in [0,1)^2.
LightSample sampleLight(const Scene& scene, int l, const Vec3& ref, const Vec2& u);

// The densities with which sampleLight picks a point (pdfA) or a direction (pdfW) of light l:
// LightSample's two fields, for any point or direction of the light (they do not depend on it).
struct LightPdf {
    float pdfA = 0.0f;
    float pdfW = 0.0f;
};
LightPdf pdfLight(const Scene& scene, int l);

// Radiance an area light emits from a point with normal n in direction w (one-sided).
Color emittedRadiance(const Light& light, const Vec3& n, const Vec3& w);

// A light particle's first vertex and direction (light tracing, BPT, photon mapping).
struct EmissionSample {
    Vec3 p, n;          // origin and its normal (point light: n unused)
    Vec3 dir;           // unit direction of emission
    Color Le;           // radiance (area, background) or intensity (point) along dir
    float pdfA = 0.0f;  // area pdf of p (point light: 1, delta position; background: of p on
                        // the disk of radius sceneRadius facing -dir)
    float pdfW = 0.0f;  // solid-angle pdf of dir
};
EmissionSample sampleEmission(const Scene& scene, int l, const Vec2& uPos, const Vec2& uDir);

// The densities sampleEmission samples with (its pdfA and pdfW), for light l, an origin with
// normal n and the unit direction dir: area light pdfA = 1 / area, pdfW = max(0, dot(n, dir)) / pi;
// point light 1 (a delta position) and 1 / (4 pi); background pdfA = 1 / (pi R^2) (the disk of
// radius R = scene.radius facing dir) and pdfW = 1 / (4 pi), as pdfLight's. Without the
// light-selection probability (Scene::lightSelectionProb). pdfA does not depend on n or dir.
struct EmissionPdf {
    float pdfA = 0.0f;
    float pdfW = 0.0f;
};
EmissionPdf pdfEmission(const Scene& scene, int l, const Vec3& n, const Vec3& dir);

// Emitted power, used to select lights proportionally to it.
float lightPower(const Scene& scene, int l);

}  // namespace ps
