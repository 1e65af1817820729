// Lesson 11's thin lens (Eq. 11.10-11.18): a camera whose rays leave a disk of radius r (the
// aperture) instead of a point, all through the point of the plane of focus (distance F in front
// of the lens) that the pinhole's ray through the same raster position meets. Points on that
// plane are sharp; the rest is blurred (depth of field). Scene syntax: `camera ... lens r focus F`
// (scenes/README.md).
//
// The student's pieces are members of the framework's Camera (declared in framework/camera.h,
// like lesson 0's generateRay and lesson 4's We) and the t = 0 connection below; implemented in
// solutions/11-classics/thinlens.cpp, lens_connection.cpp (reference) or
// assignments/11-classics/ (yours); lessons/11-classics/README.md derives every formula.
//
//   Vec3  Camera::lensPoint(u)                       z = c + r (d_x right + d_y up), d on the unit disk (11.10)
//   float Camera::pdfLens()                          p_A(z) = 1 / (pi r^2)                          (11.11)
//   Ray   Camera::lensRay(raster, z)                 from z towards the raster's point of focus     (11.12)
//   bool  Camera::lensRasterOfDirection(z, dir, raster)  where the ray (z, dir) lands on the image  (11.13)
//   float Camera::lensWe(z, dir)                     W_e(z, dir) = 1 / (pi r^2 A cos^4 theta)        (11.14)
//   float Camera::lensPdfDirection(z, dir)           p(dir | z) = 1 / (A cos^3 theta)               (11.15)
//
// The framework's pixel loop makes every camera-ray algorithm's rays through the lens
// (tasks.h's cameraRay: a lens point per sample, lens_rays.cpp hands lensRay to the framework).
// Lessons 5-7 see the camera through its camera-point functions (Camera::samplePoint, pdfPoint,
// generateRay(raster, z), rasterPosition(z, p), We(z, dir), pdfDirection(z, dir)): light tracing
// connects each light path to a lens point, and bidirectional path tracing gains t = 0.
#pragma once
#include "07-bidirectional/bpt.h"

namespace ps {

// What the technique t = 0 gives at the light subpath's vertex y_m (Eq. 11.16, 11.17): the light
// subpath y_0 .. y_m, one more step from y_m, and the lens point z that step's ray meets first. The
// full path y_0 .. y_m z has s = m + 2 vertices, all sampled from the light side.
struct LensConnection {
    bool valid = false;         // the ray meets the lens, nothing in between, W_e(z) > 0
    Color value = Color(0.0f);  // C*_{m+2,0} = beta' W_e^(j)(z -> y_m), splatted at raster with the
                                // factor 1 / (width * height) of lesson 5 (Eq. 11.17)
    Vec2 raster;                // where it lands: camera.lensRasterOfDirection(z, towards y_m)
    PathVertex lens;            // z as a path vertex: cameraVertex(scene, z)
    PathVertex light;           // m = 0 only: the new light vertex y_0 (as lightSubpath's: onLight,
                                // pointLight, infinite with sp.n towards the background)
};

// The technique t = 0 at y_m (Eq. 11.16, 11.17), for a thin-lens camera: a fresh step of the light
// walk from y_m, then its ray against the lens (camera.hitLens), the shadow ray up to it, and
// value = beta' W_e^(j). m = 0: a fresh light path start (lesson 5's startLightPath with
// rng.uniform(), rng.uniform2(), rng.uniform2(), drawn in that order; beta' = its beta; the
// subpath's own y_0 is not used); m >= 1: lesson 5's sampleAdjointBSDF at y_m (numbers
// rng.uniform2(), then rng.uniform()), beta' = y_m.beta times its weight. Not valid for a pinhole
// camera.
LensConnection connectLens(const Scene& scene, const PathVertex* y, int m, Rng& rng);

// ---- plumbing (lens_technique.cpp): t = 0 inside lesson 7's bptSample -----------------------

// The MIS weight of the path y_0 .. y_m z that connectLens made (s = m + 2, t = 0; Eq. 11.18),
// from lesson 7's weights with the lens vertex's densities from both sides: the light side's
// (pdfLightToward for m = 0, else pdfScatter Importance from y_m) and the camera side's
// (camera.pdfPoint(); y_m's from z, pdfScatter Radiance). joined (if not null): the full path,
// x_0 .. x_{m+1}, with those densities in pdfFwd / pdfRev.
float lensMisWeight(const Scene& scene, const Subpath& light, int m, const LensConnection& c, Heuristic h,
                    bool recursive, Subpath* joined = nullptr);

// What bptSample adds for t = 0 with a thin lens: connectLens at every light vertex y_m (m <=
// maxDepth), each valid one splatted at its raster position with its weight (recorder: (m + 2, 0)),
// unless opt.pathTest (`--paths`) says its path does not match: pathTest(light, {}, m + 2, 0).
// An empty camera subpath: the lens vertex z is the path's E.
void lensTechniques(const Scene& scene, const Subpath& light, Rng& rng, const BptOptions& opt, const SplatTarget& splat,
                    TechniqueRecorder* recorder);

}  // namespace ps
