// Lesson 6's path space: a light path as a point x = x0 x1 ... xk of the path space (x0 on a
// light, xk the camera: the pinhole, or a point of a camera model (framework/camera.h); k edges: "path
// length k"), the measurement contribution f(x) in
// three-point form (Eq. 6.3), the geometry term (Eq. 6.4), the solid-angle -> area conversion
// (Eq. 6.6) and the area-measure pdf p_{s,t}(x) of a path under each sampling technique (s light
// vertices, t camera vertices, Eq. 6.7-6.10). Path tracing and light tracing become two of the
// k + 1 techniques that sample the same integral (Eq. 6.2). Implemented in
// solutions/06-path-space/*.cpp (reference) or assignments/06-path-space/*.cpp (yours);
// lessons/06-path-space/README.md derives every formula (Eq. 6.1-6.12).
//
// The student's pieces: geometryTerm, pdfSolidAngleToArea, contribution, pdfTechnique.
// Everything else here is plumbing (read it, nothing to write).
#pragma once
#include <vector>
#include "05-light-tracing/lighttracer.h"
#include "film.h"
#include "integrator.h"
#include "render.h"

namespace ps {

// One vertex of a path, and of lesson 7's subpaths (the same type: a subpath is a Path too).
// Delta vertices are FLAGS, never huge numbers (Eq. 6.11).
struct PathVertex {
    SurfacePoint sp;          // position sp.p; unit normal sp.n (see below); material; sp.light:
                              // the light the vertex lies on (-1: none)
    bool onLight = false;     // on light sp.light: x0 (area, point or background), or a surface
                              // that emits (a camera ray may hit it)
    bool pointLight = false;  // a point light: a delta position, no surface, no cosine
    bool pinhole = false;     // the pinhole camera: a delta position; sp.n = camera.forward()
    bool onCamera = false;    // a point of a camera model (framework/camera.h): a camera vertex a
                              // ray can hit; on the camera's surface, sp.n = camera.forward()
    bool specular = false;    // a surface whose material is delta (mirror, glass)
    bool infinite = false;    // the background: not a point but a direction; sp.n is the unit
                              // direction from x1 towards the background, sp.p is unused
    // Lesson 7's bookkeeping along a subpath (lesson 6 leaves it at 0; Eq. 7.1, 7.3, 7.6, 7.9):
    Color beta = Color(0.0f);  // throughput of the subpath up to and including this vertex
    float pdfFwd = 0.0f;       // density of the vertex under its own subpath's sampling
    float pdfRev = 0.0f;       // density of the vertex sampled from the other direction
    double misSum = 0.0;       // recursive MIS: the partial sum B_i of Eq. 7.9

    const Vec3& p() const { return sp.p; }
    const Vec3& n() const { return sp.n; }
    // A delta position (point light or pinhole): no ray can hit it.
    bool deltaPosition() const { return pointLight || pinhole; }
    // The camera's vertex x_k (z_0 of a camera subpath).
    bool isCamera() const { return pinhole || onCamera; }
    // The vertex lies on a surface with normal sp.n (cosines count there).
    bool onSurface() const { return !pointLight && !pinhole && !infinite; }
};
// x[0] on a light, ..., x[k] the camera: path length k = x.size() - 1.
using Path = std::vector<PathVertex>;

// ---- the student's pieces ----------------------------------------------------------------

// The geometry term without visibility (Eq. 6.4): G(a, b) = |cos theta_a| |cos theta_b| / |a - b|^2,
// theta the angle between a vertex's sp.n and the edge. No cosine at a point light (the pinhole
// has its cosine, to sp.n = camera.forward()); if one end is infinite, only the finite end's
// cosine and no 1/d^2 (the infinite end's measure is solid angle, Eq. 6.5).
float geometryTerm(const PathVertex& a, const PathVertex& b);

// A solid-angle pdf pdfW of the direction from `from` towards `to`, as a pdf per unit area at
// `to` (Eq. 6.6): pdfW |cos theta_to| / d^2; without the cosine if `to` is a point light or the
// pinhole (no surface); pdfW itself if `to` is infinite (its measure is solid angle).
float pdfSolidAngleToArea(float pdfW, const PathVertex& from, const PathVertex& to);

// The measurement contribution of the path to the pixel its last edge passes through, in
// three-point form (Eq. 6.3):
//   f(x) = Le(x0 -> x1) G(x0, x1) V(x0, x1) prod_{i=1}^{k-1} f_s(x_{i-1} -> x_i -> x_{i+1}) G(x_i, x_{i+1}) V(x_i, x_{i+1})
//          * W_e^(j)(x_{k-1} -> x_k),
// W_e^(j) = width * height * camera.We(x_k, direction from x_k to x_{k-1}) (lesson 4, Eq. 4.6;
// the two-argument We also serves a camera model), V from visible(). In double: a long path's f in a scene at scale 1e-4 or 1e4 leaves
// the float range (it has a 1/d^2 per edge), while f / p stays moderate. A specular vertex contributes the coefficient of its Dirac delta
// (deltaLobe, Eq. 6.11), 0 if the directions are not its reflected / refracted pair.
DColor contribution(const Scene& scene, const Path& x);

// The area-measure pdf p_{s,t}(x) (Eq. 6.7-6.10), t = k + 1 - s, with which technique (s, t)
// samples the path: the light subpath samples x0 ... x_{s-1}, the camera subpath x_k ...
// x_{k-t+1}, and the deterministic edge x_{s-1} x_s joins them. The camera point x_k has density
// camera.pdfPoint() (1 for the pinhole: a delta position), its direction camera.pdfDirection(x_k,
// ...). 0 if the technique cannot sample the path (Eq. 6.12): t = 0 with a pinhole (no ray hits
// it; a camera model's points can be: then the light subpath samples every vertex and there is
// no joining edge), s = 0 with a point light, a specular vertex at either end of the joining edge,
// t = 1 with x_{k-1} the background (k = 1: a direction cannot be joined to the camera). Lesson
// 7's techniqueSamples is the same rule. Russian roulette is not part of p_{s,t}. In double, as f.
double pdfTechnique(const Scene& scene, const Path& x, int s);

// ---- plumbing ----------------------------------------------------------------------------

// Vertices from what the framework gives: a surface point hit by a ray (on a light if it is
// emissive; specular if its material is delta), a point on light l chosen by sampleEmission
// (the background: the direction -e.dir), the camera's: the pinhole, or the point z of a camera
// model (the one-argument form is the pinhole's vertex, also for a camera with a model).
PathVertex surfaceVertex(const Scene& scene, const SurfacePoint& sp);
PathVertex lightVertex(const Scene& scene, int l, const EmissionSample& e);
// The same for a point of light l that sampleLight chose (next-event estimation; the background:
// the direction ls.wi).
PathVertex lightVertex(const Scene& scene, int l, const LightSample& ls);
PathVertex backgroundVertex(const Scene& scene, const Vec3& towardsBackground);
PathVertex cameraVertex(const Scene& scene);
PathVertex cameraVertex(const Scene& scene, const Vec3& z);

// V(a, b): true if nothing blocks the segment between a and b (an infinite a or b: the ray
// from the finite end along the direction escapes the scene).
bool visible(const Scene& scene, const PathVertex& a, const PathVertex& b);

// Unit direction from a towards b (for an infinite b: b.sp.n; for an infinite a: -a.sp.n); the
// zero vector if the two points coincide (a point light on a surface: every BSDF and pdf of it
// is then 0, never NaN). Inline: every density and connection asks it, several times a vertex.
inline Vec3 direction(const PathVertex& a, const PathVertex& b) {
    if (b.infinite) return b.sp.n;
    if (a.infinite) return -a.sp.n;
    const Vec3 d = b.sp.p - a.sp.p;
    return glm::dot(d, d) > 0.0f ? glm::normalize(d) : Vec3(0.0f);
}

// The Dirac delta of a specular vertex with normal n, for light arriving from wLight and
// leaving towards wCamera (both unit, pointing away from the surface) (Eq. 6.11). All numbers
// are coefficients of delta_sigma(w - wCamera), the delta in the solid angle of the outgoing
// (light-flow) direction wCamera:
struct DeltaLobe {
    bool valid = false;  // wCamera is the mirror / refraction direction of wLight (to 1e-3).
                         // The numbers below are those of the lobe the two sides select
                         // (reflection on one side, refraction across; 0 under total internal
                         // reflection) even when valid is false: a walk that chose the
                         // direction itself may use them (lesson 7: a segment a fraction of a
                         // millimetre long, where a sphere touches the floor, rounds the
                         // directions between the stored positions past the tolerance).
    bool refracted = false;
    Color fs;                // f_s |cos theta_wCamera|: the lobe's share of the power (mirror:
                             // albedo; glass: Fresnel F or 1 - F)
    float pdfLight = 0.0f;   // the light subpath's sampler at the vertex (from wLight): the
                             // probability of choosing the lobe
    float pdfCamera = 0.0f;  // the camera subpath's sampler (from wCamera): the probability of
                             // the lobe times |d sigma(wCamera) / d sigma(wLight)|
                             // = (eta_L / eta_C)^2 |cos theta_L| / |cos theta_C| (1 for a mirror)
};
// `tolerance`: how far (in radians, about) wCamera may be from the exact lobe direction and still
// be valid. Directions between stored vertices carry the rounding of their float positions: pass
// deltaTolerance(...) of the three vertices (1e-3 near the origin, more far from it or on a very
// short edge: a scene moved by 1e5 rounds its positions to 8e-3).
constexpr float kDeltaTolerance = 1e-3f;
DeltaLobe deltaLobe(const Material& m, const Vec3& n, const Vec3& wLight, const Vec3& wCamera,
                    float tolerance = kDeltaTolerance);
// The direction tolerance at the specular vertex v between its neighbours a and b: 256 float steps
// of the largest coordinate over the shorter edge, at least kDeltaTolerance.
float deltaTolerance(const PathVertex& a, const PathVertex& v, const PathVertex& b);

// One path of length k sampled with technique (s, t = k + 1 - s) from rng (Eq. 6.8): a light
// subpath of s vertices (a light chosen by power, sampleEmission, then sampleBSDF in Importance
// mode), a camera subpath of t vertices (the camera point, a ray through a uniform raster
// position, then sampleBSDF in Radiance mode), joined by an edge. raster: the pixel it lands in
// (t >= 2: the camera ray's; t = 1: where x_{k-1} projects). t = 0 (s = k + 1, a camera model
// only): the light subpath's last direction must hit the camera, unoccluded; raster: where.
// valid is false if sampling failed (a miss, s = 0 ending on a non-emitter, an invalid BSDF
// sample); the estimate is then 0.
struct TechniqueSample {
    bool valid = false;
    Path x;
    Vec2 raster;
};
TechniqueSample sampleTechnique(const Scene& scene, int k, int s, Rng& rng);

// The estimate of one technique sample: f(x) / p_{s,t}(x) with the student's contribution and
// pdfTechnique (0 if the sample is invalid or p = 0).
Color techniqueEstimate(const Scene& scene, const TechniqueSample& ts, int s);

// The image of paths of length exactly k estimated by technique (s, t) alone: every iteration
// samples width * height paths and adds f / (p N) at each one's pixel (as lesson 5's splats).
// Registered for the render command as path-s0 ... path-s4 and path-t1 (s = k), with
// k = maxdepth + 1: `pathspace render SCENE --algo path-s1 --maxdepth 1` renders length 2.
RenderResult renderTechnique(const Scene& scene, int k, int s, int iterations, uint64_t seed, int threads = 1);

}  // namespace ps
