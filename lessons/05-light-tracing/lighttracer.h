// Lesson 5's light tracer: paths that start on the lights and carry power (Eq. 5.2), scatter
// with the adjoint BSDF (Eq. 5.6-5.8), and connect every vertex to the pinhole, adding what it
// sends there to the pixel it projects to (Eq. 5.3-5.5). It estimates every pixel of the image
// at once from the light side of the measurement equation (lesson 4, Eq. 4.11). Implemented in
// solutions/05-light-tracing/*.cpp (reference) or assignments/05-light-tracing/*.cpp (yours);
// lessons/05-light-tracing/README.md derives every formula (Eq. 5.1-5.10).
//
// maxDepth is the largest number of bounces a path may have, as in lesson 3: a light's point
// connected straight to the camera has 0 bounces, the k-th surface a particle hits k.
#pragma once
#include "03-path-tracing/pathtracer.h"
#include "04-measurement/measurement.h"
#include "film.h"

namespace ps {

// The first vertex of a light path and the particle that leaves it (Eq. 5.2).
struct LightPathStart {
    bool valid = false;  // false if there is no light or the sample has pdf 0
    int light = -1;      // index into scene.lights
    SurfacePoint y0;     // the point on the light (lesson 4's emissionPoint)
    float pdfA = 0.0f;   // P(l) p_A(y0): the density of choosing y0 (point light: P(l))
    Ray ray;             // the particle's first ray, leaving y0
    Color beta;          // the particle's power Le |cos| / (P(l) p_A p_omega) (Eq. 5.2)
};

// Chooses a light by power with uLight and samples a point and a direction on it with
// (uPos, uDir) through sampleEmission (Eq. 5.2). Background: the particle comes from the disk
// sampleEmission chooses; it is valid too.
LightPathStart startLightPath(const Scene& scene, float uLight, const Vec2& uPos, const Vec2& uDir);

// What connecting a vertex y to the pinhole gives (Eq. 5.3-5.5).
struct CameraConnection {
    bool valid = false;       // the camera sees y: in front of it, inside the image, unoccluded
    Vec2 raster;              // where y lands on the image (camera.rasterPosition)
    Vec3 wCam;                // unit direction from y towards the pinhole (the camera point z)
    float importance = 0.0f;  // W_e^(j)(e -> y) G(y, e) / p(e): the pixel's sensor (lesson 4,
                              // Eq. 4.6) times the geometry term cos(theta_e) |cos(theta_y)| / d^2,
                              // without |cos(theta_y)| when y is not on a surface (a point light),
                              // over the density of the camera point e, camera.pdfPoint() (1 for
                              // the pinhole; a camera model's point's, framework/camera.h)
};

// Connects y to the camera point z (Eq. 5.5): the pinhole camera.position(), or a point of the
// camera's model (framework/camera.h), for which camera.rasterPosition(z, ...) and
// camera.We(z, ...) hold the model's own raster position and importance (for the pinhole they are
// the one-point forms).
// onSurface: y lies on a surface with normal y.n (false for a point light's position).
CameraConnection connectToCamera(const Scene& scene, const SurfacePoint& y, bool onSurface, const Vec3& z);
// The same for the pinhole, z = camera.position() (plumbing).
CameraConnection connectToCamera(const Scene& scene, const SurfacePoint& y, bool onSurface);

// The adjoint BSDF (Eq. 5.6-5.8): a particle arrived at a surface with normal n from wLight
// (unit, pointing back to where it came from); sample the direction s.wi it leaves in, and the
// factor its power is multiplied by, s.weight = f*(wLight -> s.wi) |cos(theta_wi)| / pdf with
// f*(wLight -> wi) = f(wi -> wLight) read as evalBSDF(m, n, wi, wLight): the arguments swapped
// compared with the path tracer. Refraction keeps the power (no (eta_i / eta_t)^2, Eq. 5.8).
// u picks the direction, uLobe reflection or refraction. False for an invalid sample.
bool sampleAdjointBSDF(const Material& m, const Vec3& n, const Vec3& wLight, const Vec2& u, float uLobe, BSDFSample& s);

// What to do at a vertex y_k of the light walk (lesson 3's WalkVertex: sp, wo towards where the
// particle came from, beta the particle's power arriving there; y_0 is the point on the light,
// with beta = start.beta), given the path's start; return false to end the walk there. The walk
// calls it before it samples the direction there (it may draw numbers from the walk's rng).
using LightWalkVisitor = std::function<bool(const WalkVertex& v, const LightPathStart& start)>;

// The particle's random walk (Eq. 5.1, 5.2, 5.6-5.8): startLightPath with rng.uniform(),
// rng.uniform2(), rng.uniform2(), drawn in that order (nothing if it is not valid), visit y0,
// then lesson 3's walk (randomWalk) from y0's ray with the particle's power start.beta,
// scattering with the adjoint BSDF (sampleAdjointBSDF), visiting every surface the particle hits
// (not a miss: a particle that leaves the scene is gone), at most opt.maxDepth bounces; Russian roulette as lesson 3's on the
// product of the scattering weights alone (the throughput since y0, without start.beta): q =
// opt.survival(throughput, bounces). The options' direction sampler and continuation rule work as
// in lesson 3's walk. Lesson 7's light subpath is this walk too; lesson 8's photons take it with a
// survival of their own.
void lightWalk(const Scene& scene, Rng& rng, const WalkOptions& opt, const LightWalkVisitor& visit);

// One light path (Eq. 5.1-5.4): the light walk, whose visitor connects y0 and every
// non-specular vertex to the camera and adds each connection's contribution through
// out.add(raster, value) (a SplatTarget, framework/film.h). Every connection goes to one camera
// point z, drawn before the walk: the pinhole (no number drawn), or a point of the camera's model.
void traceLightPath(const Scene& scene, Rng& rng, int maxDepth, const SplatTarget& out);
// The same with the light walk's options given (lesson 3's WalkOptions: its maximum depth, and a
// survival function, direction sampler or continuation rule of the caller's); the form above is
// this with {maxDepth} (plumbing, light_integrator.cpp).
void traceLightPath(const Scene& scene, Rng& rng, const WalkOptions& opt, const SplatTarget& out);

}  // namespace ps
