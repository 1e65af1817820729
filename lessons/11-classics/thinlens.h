// Lesson 11's thin lens (Eq. 11.10-11.18): a camera whose rays leave a disk of radius r (the
// aperture) instead of a point, all through the point of the plane of focus (distance F in front
// of the lens) that the pinhole's ray through the same raster position meets. Points on that
// plane are sharp; the rest is blurred (depth of field). Scene syntax: `camera ... lens r focus F`
// (scenes/README.md): the framework's camera model registry (framework/camera.h) reaches ThinLens
// through that keyword (lens_camera.cpp).
//
// The student's pieces are ThinLens's members below and the t = 0 connection; implemented in
// solutions/11-classics/thinlens.cpp, lens_connection.cpp (reference) or assignments/11-classics/
// (yours); lessons/11-classics/README.md derives every formula.
//
// Every algorithm that asks the camera through its functions of the camera point z (Camera::
// samplePoint, pdfPoint, generateRay(raster, z), rasterPosition(z, p), We(z, dir), pdfDirection(z,
// dir), hit) renders the lens: the framework's pixel loop, light tracing (each light path joins
// a lens point), bidirectional path tracing, which gains the technique t = 0 here (lesson 7's
// extra techniques, lens_technique.cpp).
#pragma once
#include "07-bidirectional/bpt.h"

namespace ps {

// The thin lens: a disk of radius `radius` about the pinhole's position, spanned by its right()
// and up(), sharp at the plane `focus` in front of it; every other number is the pinhole camera's.
class ThinLens : public CameraModel {
public:
    ThinLens(const Camera& pinhole, float radius, float focus);
    float radius() const { return lensRadius_; }
    float focus() const { return focus_; }

    // ---- the student's pieces (thinlens.cpp). A lens point z lies on the disk; dir is a unit
    // direction leaving z. --------------------------------------------------------------------
    // The lens point for u in [0, 1)^2: uniform on the lens, by lesson 1's concentric map (Eq. 11.10).
    Vec3 lensPoint(const Vec2& u) const;
    // Its density per unit area on the lens (Eq. 11.11).
    float pdfLens() const;
    // The ray from lens point z through raster position `raster`: towards the point of the plane of
    // focus that the pinhole's ray through `raster` meets (Eq. 11.12).
    Ray lensRay(const Vec2& raster, const Vec3& z) const;
    // Raster position of the ray (z, dir) (dir of any length): where its point on the plane of
    // focus is seen from the lens centre; false if dir points behind the lens or the position is
    // outside the image (Eq. 11.13).
    bool lensRasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const;
    // Importance W_e(z, dir) emitted by lens point z along dir, normalised over the lens and the
    // whole image (Eq. 11.14); 0 outside the image.
    float lensWe(const Vec3& z, const Vec3& dir) const;
    // Solid-angle pdf of dir at z for rays through uniformly chosen raster positions (Eq. 11.15).
    float lensPdfDirection(const Vec3& z, const Vec3& dir) const;

    // ---- the camera model (plumbing, lens_camera.cpp): the pieces above, and the disk's geometry.
    Vec3 samplePoint(const Vec2& u) const override { return lensPoint(u); }
    float pdfPoint() const override { return pdfLens(); }
    Ray ray(const Vec2& raster, const Vec3& z) const override { return lensRay(raster, z); }
    bool rasterOfDirection(const Vec3& z, const Vec3& dir, Vec2& raster) const override {
        return lensRasterOfDirection(z, dir, raster);
    }
    float We(const Vec3& z, const Vec3& dir) const override { return lensWe(z, dir); }
    float pdfDirection(const Vec3& z, const Vec3& dir) const override { return lensPdfDirection(z, dir); }
    // Where a ray meets the lens from the front (travelling against forward()): t in (0, ray.tMax)
    // and the point z on the disk.
    bool hit(const Ray& ray, float& t, Vec3& z) const override;
    std::string describe() const override;

private:
    Camera pinhole_;  // the camera the lens replaces: its frame, image and rays
    Vec3 eye_, forward_, right_, up_;
    float lensRadius_ = 0.0f, focus_ = 1.0f;
};

// The thin lens of a scene's camera; nullptr for any other camera.
const ThinLens* thinLens(const Camera& camera);

// What the technique t = 0 gives at the light subpath's vertex y_m (Eq. 11.16, 11.17): the light
// subpath y_0 .. y_m, one more step from y_m, and the lens point z that step's ray meets first. The
// full path y_0 .. y_m z has s = m + 2 vertices, all sampled from the light side.
struct LensConnection {
    bool valid = false;         // the ray meets the lens, nothing in between, W_e(z) > 0
    Color value = Color(0.0f);  // C*_{m+2,0} = beta' W_e^(j)(z -> y_m), splatted at raster with the
                                // factor 1 / (width * height) of lesson 5 (Eq. 11.17)
    Vec2 raster;                // where it lands: camera.rasterOfDirection(z, towards y_m)
    PathVertex lens;            // z as a path vertex: cameraVertex(scene, z)
    PathVertex light;           // m = 0 only: the new light vertex y_0 (as lightSubpath's: onLight,
                                // pointLight, infinite with sp.n towards the background)
};

// The technique t = 0 at y_m (Eq. 11.16, 11.17), for a thin-lens camera: a fresh step of the light
// walk from y_m, then its ray against the lens (camera.hit), the shadow ray up to it, and
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

// The technique t = 0, registered as one of lesson 7's extra techniques: with a thin lens, connectLens
// at every light vertex y_m (m <= maxDepth), each valid one splatted at its raster position with
// its weight (recorder: (m + 2, 0)), unless opt.techniqueFilter (`--paths`) says no:
// techniqueFilter(light, {}, m + 2, 0), an empty camera subpath (the lens vertex z is the path's E).
// Nothing, and no number drawn, for any other camera.
void lensTechniques(const Scene& scene, const Subpath& light, Rng& rng, const BptOptions& opt, const SplatTarget& splat,
                    TechniqueRecorder* recorder);

}  // namespace ps
