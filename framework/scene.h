// The scene: shapes, materials, lights, camera, the BVH over the shapes, default settings,
// and the capabilities recorded at load time (what kinds of light, BSDF and camera it has).
#pragma once
#include <map>
#include <string>
#include <vector>
#include "bsdf.h"
#include "bvh.h"
#include "camera.h"
#include "geometry.h"
#include "light.h"

namespace ps {

enum class ShapeKind : uint8_t { Triangle, Sphere };

struct Primitive {
    ShapeKind shape = ShapeKind::Triangle;
    uint32_t index = 0;  // into Scene::triangles or Scene::spheres
    int material = -1;   // into Scene::materials
    int light = -1;      // into Scene::lights if the primitive emits, else -1
};

// A setting some lesson's algorithm takes, registered by that lesson (Registry<RenderParameter>,
// keyed by NAME), as camera models are: one or more numbers, `render NAME V1 .. Vn` in a scene file
// and `--NAME V1,..,Vn` on the command line (render, converge, pyramid; there one value may stand
// for all n). The loader and the command line refuse an unregistered name, a wrong count of
// values, a value that is not a finite number and values `check` refuses, naming the line or the
// option, before any work; the values go to RenderSettings::parameters, where the algorithm reads
// them (renderParameter, renderParameterValues).
struct RenderParameter {
    std::string help;              // one line: what it sets and its default, for the usage and messages
    std::string valueNames = "V";  // one word per value, for the usage: "N M", "R G B"
    int count = 1;                 // how many numbers it takes
    // Empty if the values (count of them, each finite) are allowed, else what is wrong with them
    // ("must be a positive number"); nullptr: any finite numbers.
    std::string (*check)(const std::vector<float>& values) = nullptr;
};
// What is wrong with `values` for parameter p, empty if nothing: their count (p.count), a value
// that is not finite, then p.check. The loader and the command line both ask it.
std::string renderParameterProblem(const RenderParameter& p, const std::vector<float>& values);

// The largest image a scene may ask for: each side at most kMaxResolution, and at most
// kMaxPixels pixels in all. A render keeps state per pixel, measured with /usr/bin/time on the
// Cornell spheres at 512^2 and 1024^2: about 60 bytes for pt and the first-hit views (the film's
// double sums and an iteration's image), 126 for lt and bpt (splat lists), 230-250 for pm and
// pssmlt, 510 for pt-adrrs, 720-730 for mmlt and ppm (scenes/README.md, "Memory"): at
// kMaxPixels every algorithm fits in 4 GiB (the grader's limit of a process).
constexpr int kMaxResolution = 16384;
constexpr long long kMaxPixels = 1LL << 22;  // 4,194,304: 2048 x 2048, 4096 x 1024

// Defaults a scene file may set; the command line overrides them.
struct RenderSettings {
    int spp = 16;
    int maxDepth = 8;  // maximum number of bounces; 0 = only emission seen directly
    std::string algo = "eyelight";
    int algoLine = 0;  // the scene file line that set algo (for messages), 0 if none
    // The render parameters set (RenderParameter above: the scene's `render NAME V..`, then the
    // command line's `--NAME V,..`), by name, each with its parameter's count of values.
    std::map<std::string, std::vector<float>> parameters;
    // Integrators leave out work the capabilities show cannot contribute (Integrator::leftOut);
    // false (`--no-prune`) makes them do all of it, to check that pruning changes nothing.
    bool prune = true;
};

// The (first) value set for render parameter `name`, or `fallback` if none is set.
float renderParameter(const RenderSettings& settings, const std::string& name, float fallback);
// The values set for render parameter `name`, or `fallback` if none are set.
std::vector<float> renderParameterValues(const RenderSettings& settings, const std::string& name,
                                         const std::vector<float>& fallback);

// What a scene has, recorded at load time so integrators can leave out what it does not need.
struct Capabilities {
    bool areaLights = false, pointLights = false, backgroundLight = false;
    bool diffuse = false, glossy = false, mirror = false, dielectric = false;
    bool pinholeCamera = true;
    std::string cameraModel = "pinhole";  // the camera model's keyword (CameraModel::describe's first word)
    bool hasLights() const { return areaLights || pointLights || backgroundLight; }
    bool hasDeltaBSDF() const { return mirror || dielectric; }
    bool hasNonDeltaBSDF() const { return diffuse || glossy; }
    // Paths no unbiased technique can sample: a point light reached from a pinhole camera
    // through specular vertices only (L S+ E). They exist iff both ends are delta and some
    // material is specular; their contribution is 0 in every technique.
    bool unsampleablePaths() const { return pointLights && pinholeCamera && hasDeltaBSDF(); }
    std::string describe() const;
};

// A quad of the scene file as it was written: its corners (counter-clockwise seen from the side
// its normal points to) and its two triangles, prims[prim] = corners (1, 2, 3) and
// prims[prim + 1] = (1, 3, 4). Nothing renders from it (the triangles are the geometry); an
// algorithm that works on the surfaces as written (patches, say) reads the quads.
struct Quad {
    Vec3 corners[4];
    uint32_t prim = 0;  // the first of its two primitives
    int line = 0;       // the scene file line
};

class Scene {
public:
    std::string path;  // the scene file, for messages
    // The files it was read from: the scene file (loadScene), then its meshes and their material
    // libraries, in the order named. The program's commands never write over any of them.
    std::vector<std::string> inputFiles;
    Camera camera;
    RenderSettings settings;
    std::vector<Material> materials;
    std::vector<Triangle> triangles;
    std::vector<Sphere> spheres;
    std::vector<Primitive> prims;
    std::vector<Quad> quads;  // the scene file's quads, in file order (a record: see Quad)
    std::vector<Light> lights;
    int background = -1;            // index of the background light, -1 if none
    Distribution1D lightSelection;  // picks lights proportionally to their power
    Capabilities caps;
    AABB bounds;
    Vec3 center;  // bounding sphere of the geometry and the camera
    float radius = 1.0f;
    BVH bvh;
    // What finalize noticed but did not refuse, one line each (loadScene prints them as
    // "pathspace: warning: ..."): e.g. coordinates so far from the origin that float cannot
    // resolve the scene's small features.
    std::vector<std::string> warnings;

    // Call after filling the vectors above: builds the BVH, area lights' tables, the light
    // selection distribution, the bounding sphere and the capabilities.
    void finalize();

    // Closest hit in (0, ray.tMax); on a hit ray.tMax becomes the hit distance.
    bool intersect(Ray& ray, SurfacePoint& sp) const;
    // Any hit in (0, ray.tMax) (shadow rays).
    bool occluded(const Ray& ray) const;

    // A ray leaving surface point sp in direction dir (offset, and never re-hitting sp's
    // triangle).
    Ray spawnRay(const SurfacePoint& sp, const Vec3& dir) const;
    // A shadow ray from sp to the surface point q (both ends offset): occluded() tells
    // whether the two see each other.
    Ray spawnRayTo(const SurfacePoint& sp, const SurfacePoint& q) const;
    // A shadow ray from sp to a point not on a surface (a point light, the pinhole).
    Ray spawnRayTo(const SurfacePoint& sp, const Vec3& q) const;
    // All three treat a point light that lies on surfaces (Light::surfaceScale > 0) as a point
    // in each of their planes: as origin (sp.light is the light) and as target (q is its
    // position), the ray's end is offset off every one of those planes to the side the ray goes
    // to (lightRayPoint), so it never hits them at t ~ 0 (float rounding makes the watertight
    // test's t of an origin in a triangle's plane a random +-ulps, which would scatter or block
    // the light at its own position).
    std::vector<int> surfacePointLights;  // indices of such lights (finalize)

    // Light index for u in [0,1) and its probability.
    int selectLight(float u, float& prob) const;
    float lightSelectionProb(int l) const { return lightSelection.pmf(static_cast<size_t>(l)); }
    // Background radiance seen along a ray that leaves the scene.
    Color backgroundRadiance() const { return background >= 0 ? lights[background].Le : Color(0.0f); }

    // Point and normal at barycentrics (b1, b2) of a triangle, or for a sphere direction.
    SurfacePoint surfacePoint(uint32_t prim, const Vec3& p) const;

private:
    // What the primitive test reads, in the BVH's item order (a leaf's primitives are adjacent):
    // the triangle itself, no lookup through prims and triangles; and what the surface point of
    // a hit needs, so that no ray looks up prims (52 bytes: reading prims[] for the material cost
    // a cache miss per hit, 8-13 % of the speed of incoherent rays, bench/README.md).
    struct Item {
        Triangle tri;                    // the triangle (unused for a sphere)
        uint32_t prim = kNoPrimitive;    // index into prims
        uint32_t sphere = kNoPrimitive;  // index into spheres, kNoPrimitive for a triangle
        int material = -1, light = -1;   // prims[prim]'s, for the surface point of a hit
    };
    std::vector<Item, LargePageAllocator<Item>> items_;
    // intersect() and occluded() run one of two copies of the same code: for AVX2, when the CPU
    // has it, or for the x86-64 baseline (scene.cpp; useAvx2Tracing).
    bool closestHit(Ray& ray, SurfacePoint& sp) const;
    bool anyHit(const Ray& ray) const;
    bool closestHitAvx2(Ray& ray, SurfacePoint& sp) const;
    bool anyHitAvx2(const Ray& ray) const;
    // The light sp stands for if it is a point light lying on a surface (surfaceScale > 0), else nullptr.
    const Light* surfaceLight(const SurfacePoint& sp) const;
    void findSurfacePointLights();
};

// Rays traced by this thread since the last call (for rays/s in render summaries).
uint64_t takeRayCount();

// Whether Scene::intersect and occluded run their AVX2 copy (x86-64 CPUs that have AVX2; the
// default unless PATHSPACE_NO_AVX2 is set in the environment) or the baseline one. Both give the
// same bits; tests switch between them (not while rays are traced). Returns the new setting:
// false where there is no AVX2 copy or CPU support for it.
bool useAvx2Tracing(bool on);

}  // namespace ps
