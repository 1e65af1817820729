// Lesson 7's bidirectional path tracer: a light subpath y_0 .. y_{s-1} and a camera subpath
// z_0 .. z_{t-1} (Eq. 7.1), joined by one connection into a full path for every (s, t)
// (Eq. 7.2-7.4), each technique weighted by multiple importance sampling with the balance or
// power heuristic, computed from the full list of pdfs p_0 .. p_{k+1} of the joined path
// (Eq. 7.5-7.7) or recursively with O(1) work per vertex (Eq. 7.8-7.10). Implemented in
// solutions/07-bidirectional/*.cpp (reference) or assignments/07-bidirectional/*.cpp (yours);
// lessons/07-bidirectional/README.md derives every formula (Eq. 7.1-7.12).
//
// One vertex type: lesson 6's PathVertex (06-path-space/paths.h), with its flags (onLight,
// pointLight, pinhole, specular, infinite; the background's sp.n points from the scene towards
// the background) and the subpath fields beta, pdfFwd, pdfRev, misSum; the light a vertex lies on
// is sp.light. Lesson 6's pieces do the geometry here too: direction, geometryTerm,
// pdfSolidAngleToArea (Eq. 6.6 = 7.3's conversion), deltaLobe, and surfaceVertex, cameraVertex,
// backgroundVertex build the vertices.
//
// Conventions. Every pdf of a vertex is per unit AREA at that vertex, except at a vertex at
// infinity (the background), where it is per unit solid angle (Eq. 7.3). pdfFwd is the density
// with which the vertex was sampled by its own subpath, pdfRev the density with which the other
// direction would sample it (from the next vertex of its subpath, Eq. 7.6). A specular vertex's
// scattered direction is a Dirac delta; its density is the COEFFICIENT of that delta (deltaLobe's
// lobe probability, converted to area like any other pdf, Eq. 7.7a). Every technique that can
// sample a path carries each specular delta exactly once, so the coefficients are what (7.5)
// compares. The pinhole is chosen with probability 1 and a point light with P(l) (delta
// positions: coefficients again); a density that is 0 means "cannot be sampled this way".
//
// A camera model (framework/camera.h, e.g. a lens): z_0 is a point of the camera
// (PathVertex::onCamera), sampled with camera.pdfPoint() per unit area, and no longer a delta
// position: a light subpath can hit it, which is the technique t = 0 (a later lesson's extra
// technique adds it to bptSample, below). For a pinhole camera.pdfPoint() is 1 and every camera
// function of z is the pinhole's.
#pragma once
#include <functional>
#include <vector>
#include "02-direct-mis/mis.h"
#include "05-light-tracing/lighttracer.h"
#include "06-path-space/paths.h"

namespace ps {

// A subpath: y_0 (on a light) .. y_{s-1}, or z_0 (the camera: the pinhole, or a model's point) ..
// z_{t-1} (Eq. 7.1).
using Subpath = std::vector<PathVertex>;

// ---- vertex pdfs (vertex_pdfs.cpp), one function for sampling and for MIS (Eq. 7.3) ----

// Density of choosing the light vertex v itself (Eq. 7.3), from pdfEmission (framework/light.h):
// P(l) / area for an area light, P(l) for a point light, P(l) * 1 / (4 pi) for the
// background (solid angle).
// v.sp.light is the light's index; v may be a camera-path vertex that hit an emitter.
float pdfLightOrigin(const Scene& scene, const PathVertex& v);

// Area density with which the light at `light` emits towards `to` (the light subpath's second
// vertex, Eq. 7.3), from pdfEmission: area light: cos(theta) / pi about its normal (0 behind
// it), point light: 1 / (4 pi), both converted with pdfSolidAngleToArea; background:
// 1 / (pi R^2) * |cos theta_to| (the disk of sampleEmission, R = scene.radius).
float pdfLightToward(const Scene& scene, const PathVertex& light, const PathVertex& to);

// Area density with which `cur` samples `next` (Eq. 7.3, 7.7a): cur is the camera (isCamera()):
// camera.pdfDirection(cur's position, direction); a surface: pdfBSDF(material, n, towards prev, towards next); prev may be null
// only for the camera. A specular cur: the coefficient of its delta, lesson 6's deltaLobe,
// which depends on the direction of the walk: mode Importance (walking with the light, as the
// light subpath: prev is on the light side) deltaLobe(m, n, towards prev, towards next).pdfLight;
// mode Radiance (walking against it, as the camera subpath) deltaLobe(m, n, towards next,
// towards prev).pdfCamera (it carries the refraction's eta^2 Jacobian), even if the lobe is not
// `valid` (rounding on a very short segment; see DeltaLobe).
// Always through pdfSolidAngleToArea.
float pdfScatter(const Scene& scene, const PathVertex* prev, const PathVertex& cur, const PathVertex& next,
                 Transport mode);

// One scattering event: vertex `cur` (on a surface) between its neighbour on the light side and
// its neighbour on the camera side, f and both its densities in one call (plumbing,
// techniques.cpp; Eq. 7.2, 7.3, 7.6): what a connection at cur needs for its value and its MIS.
// Where f is 0 the connection adds nothing and the densities are left at 0 (not evaluated).
struct Scattering {
    Color f = Color(0.0f);          // f_s(light side -> cur -> camera side): evalBSDF(m, n, towards the
                                    // camera side, towards the light side) (0 at a delta BSDF)
    float pdfTowardsCamera = 0.0f;  // area density of the camera-side vertex when a light subpath leaves
                                    // cur: pdfScatter(light side, cur, camera side, Importance)
    float pdfTowardsLight = 0.0f;   // area density of the light-side vertex when a camera subpath leaves
                                    // cur: pdfScatter(camera side, cur, light side, Radiance)
};
Scattering scatteringAt(const Scene& scene, const PathVertex& lightSide, const PathVertex& cur,
                        const PathVertex& cameraSide);

// ---- the subpaths' survival (survival.cpp), Eq. 7.1a ----

// The probability q(x) that a subpath goes on from a surface vertex x of material m (Eq. 7.1a):
// a number of the material alone, the same for the light and the camera subpath whatever the
// directions at x (what lets (7.7c) hold it exactly, section 1.6).
float subpathSurvival(const Material& m);

// The subpaths' continuation rule (lesson 3's WalkOptions::continuation, Eq. 3.10 with Eq. 7.1a):
// at the walk's vertex v (a surface the walk may leave), one continuation with probability q(v)
// and none otherwise, drawing its number from rng only when q < 1; Continuations::beta and
// roulette as Eq. 3.10 asks of a rule that decides survival at the vertex itself (the walk's own
// Eq. 3.5 no longer plays on a subpath).
Continuations subpathContinuation(const Scene& scene, const WalkVertex& v, Rng& rng);

// ---- subpaths (light_subpath.cpp, camera_subpath.cpp), Eq. 7.1 ----

// The light subpath: at most maxDepth + 1 vertices (y_0 on a light, then one per bounce): lesson
// 5's lightWalk, whose visitor stores each vertex, surviving by subpathContinuation (Eq. 7.1a) from
// y_1 on. Fills beta, pdfFwd, the pdfRev of y_{i-2} once y_i exists, the flags, and, after each
// vertex, updateMisSum(path, i, h). Clears path first.
void lightSubpath(const Scene& scene, Rng& rng, int maxDepth, Heuristic h, Subpath& path);

// What to do once a camera subpath vertex z_i (i >= 1) is stored, with its pdfFwd and misSum
// (Eq. 7.9; z_{i-2}'s pdfRev known): a later algorithm's work at every camera vertex (merging it
// with the light vertices nearby, say). path holds z_0 .. z_i. Return false to end the subpath.
using CameraVertexVisitor = std::function<bool(const Subpath& path)>;

// The camera subpath through raster position `raster`: z_0 the camera point (cameraVertex of
// camera.samplePoint(rng): the pinhole, or a model's point drawn from rng), then lesson 3's
// cameraWalk (surviving by subpathContinuation, Eq. 7.1a, from z_1 on), whose visitor stores one
// vertex per intersection and hands it to `visit` (if set); at
// most maxDepth + 2 vertices; a ray that leaves the scene ends it with a vertex at infinity if
// there is a background. Clears path first.
void cameraSubpath(const Scene& scene, Rng& rng, const Vec2& raster, int maxDepth, Heuristic h, Subpath& path,
                   const CameraVertexVisitor& visit = nullptr);

// ---- the connection (connect.cpp), Eq. 7.2, 7.4, 7.6 ----

// The new reverse pdfs the connection of y_{s-1} and z_{t-1} gives (Eq. 7.6): of the two
// endpoints and of the vertices before them. 0 where there is no such vertex.
struct ReversePdfs {
    float lightEnd = 0.0f;    // y_{s-1} sampled from z_{t-1}
    float lightPrev = 0.0f;   // y_{s-2} sampled from y_{s-1} (arriving from z_{t-1})
    float cameraEnd = 0.0f;   // z_{t-1} sampled from y_{s-1} (s = 0: pdfLightOrigin)
    float cameraPrev = 0.0f;  // z_{t-2} sampled from z_{t-1} (s = 0: pdfLightToward)
};
// y points to the s light vertices, z to the t camera vertices (s + t >= 2, t >= 1).
ReversePdfs connectionPdfs(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t);

struct Connection {
    bool valid = false;
    Color value = Color(0.0f);  // unweighted contribution C*_{s,t} (Eq. 7.2); t = 1: to splat
    Vec2 raster;                // t = 1: where the light vertex lands on the image
    PathVertex sampledLight;    // s = 1: the light vertex sampled for this connection (it
                                // replaces the light subpath's y_0, Eq. 7.2)
    ReversePdfs rev;            // filled by connect() when valid
};

// The four kinds of connection (Eq. 7.4), one function each: C*_{s,t} = beta^L_{s-1} c_{s,t}
// beta^E_{t-1} (Eq. 7.2) in `value`, valid when it is not black and the shadow ray (if any) is
// unoccluded. y points to the light subpath's first s vertices, z to the camera subpath's first t.
// A specular endpoint gives nothing (evalBSDF of a delta BSDF is 0 for every given pair of
// directions); bptSample does not even call them there unless pruning is off (Eq. 7.12).

// s = 0, t >= 2: z_{t-1} is on an emitter or at infinity: c = Le(z_{t-1} -> z_{t-2}).
Connection connectEmitter(const Scene& scene, const PathVertex* z, int t);

// t = 1, s >= 1: y_{s-1} joined to the camera point z0 (the camera subpath's z_0: the pinhole, or
// a camera model's point) by lesson 5's connectToCamera (c = f W_e G; for s = 1 the light's own
// emission towards the camera); raster: where it lands. Not valid for a background y_0 (a
// direction cannot be joined to the camera).
Connection connectCamera(const Scene& scene, const PathVertex* y, int s, const PathVertex& z0);
// The same joined to the pinhole's vertex cameraVertex(scene) (plumbing, techniques.cpp).
Connection connectCamera(const Scene& scene, const PathVertex* y, int s);

// s = 1, t >= 2: a new light vertex for z_{t-1} (next-event estimation, lesson 2: the light by
// scene.selectLight(uLight), the point by sampleLight(uPos)) in sampledLight, with pdfFwd =
// pdfLightOrigin and beta = 1 / pdfFwd; c = Le G f. Not valid at a background z_{t-1}.
Connection connectLight(const Scene& scene, const PathVertex* z, int t, float uLight, const Vec2& uPos);

// s, t >= 2: y_{s-1} and z_{t-1} joined by a shadow ray: c = f G f, both f and the connection's
// reverse pdfs (rev, Eq. 7.6) from scatteringAt at the two endpoints.
Connection connectVertices(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t);

// Technique (s, t) for the given subpaths (plumbing, techniques.cpp; s <= light.size() except
// s = 1, t >= 2; t <= camera.size(), t >= 1): the connection of its kind, then, if valid and the
// kind did not fill them (s or t < 2), rev = connectionPdfs. For t = 1 sampledLight is light[0] (the MIS reads y from it whenever s = 1).
Connection connect(const Scene& scene, const Subpath& light, const Subpath& camera, int s, int t, float uLight,
                   const Vec2& uPos);

// ---- MIS weights (mis_full.cpp, mis_recursive.cpp), Eq. 7.5-7.10 ----

// Whether technique s' of a full path of n vertices x_0 .. x_{n-1} (x_0 on the light, x_{n-1}
// the camera) can sample it (Eq. 7.7): t' = n - s' >= 1, or t' = 0 when x_{n-1} is a point on a
// camera model (no joining edge then); s' = 0 needs x_0 not a point light; otherwise
// x_{s'-1} and x_{s'} both non-specular, and not a background vertex joined straight to the
// camera (s' = 1, t' = 1, x_0 infinite).
bool techniqueSamples(const PathVertex* x, int n, int sPrime);

// w_{s,t} from the full list p_0 .. p_n of the joined path's techniques (Eq. 7.5-7.7): build
// x_0 .. x_{n-1} (y then z reversed), with pL[i] (density from the light side) and pE[i] (from
// the camera side) from pdfFwd/pdfRev and the connection's rev; p_s' = prod_{i<s'} pL[i]
// prod_{i>=s'} pE[i] (the stored numbers as they are: no 0 is replaced), and w = p_s^b / sum over sampling techniques of p_s'^b.
// y: s vertices (s = 1: &c.sampledLight), z: t vertices. t = 0 (a camera model): y holds the whole
// path, its last vertex on the camera; rev.lightEnd and rev.lightPrev are then the camera
// side's densities of y_{s-1} (camera.pdfPoint()) and y_{s-2}.
float misWeightFull(const PathVertex* y, int s, const PathVertex* z, int t, const ReversePdfs& rev, Heuristic h);

// The recursive partial sum (Eq. 7.9) for vertex i of a subpath, once path[i-2].pdfRev is
// known: B_0 = B_1 = 0, B_i = r_{i-2}^b (c_{i-2} + B_{i-1}), r_j = pdfRev/pdfFwd of path[j]
// (0 if pdfFwd is 0), c_j whether the connection may sit just before path[j] (Eq. 7.10).
// Light subpaths: c_0 = not a point light; camera subpaths: c_0 = 0 at a pinhole, 1 at a camera
// model's point (t = 0). Stores it in path[i].misSum.
void updateMisSum(Subpath& path, size_t i, Heuristic h);

// The same weight as misWeightFull with O(1) work (Eq. 7.8-7.10), from the endpoints' misSum
// (t = 0: no camera subpath, z unused).
float misWeightRecursive(const PathVertex* y, int s, const PathVertex* z, int t, const ReversePdfs& rev, Heuristic h);

// ---- the integrator (plumbing, bpt_integrator.cpp) ----

struct BptOptions {
    Heuristic heuristic = Heuristic::Power;
    bool recursive = true;  // misWeightRecursive (else misWeightFull)
    bool prune = true;      // leave out what the scene cannot use (Eq. 7.12)
    // The technique filter: if set, technique (s, t) adds its path only if
    // techniqueFilter(light, camera, s, t) says so (an algorithm that renders only some paths sets
    // it). The random numbers of s = 1 are drawn before the test, so every technique meets the
    // same numbers either way. An extra technique asks it too, with its own (s, t).
    std::function<bool(const Subpath& light, const Subpath& camera, int s, int t)> techniqueFilter;
    // More techniques than (s, t) for the same paths (a caller whose estimator also samples them
    // another way): if set, each connection's weight w_{s,t} (Eq. 7.8) becomes
    // techniqueWeight(w_{s,t}, y, s, z, t, rev), the weight among all of the caller's techniques;
    // the arguments are those of misWeightRecursive.
    std::function<float(float w, const PathVertex* y, int s, const PathVertex* z, int t, const ReversePdfs& rev)>
        techniqueWeight;
};

// What one pixel sample's techniques gave, for per-technique images (Veach's pyramid).
struct TechniqueRecorder {
    virtual ~TechniqueRecorder() = default;
    // t >= 2: the pixel of the camera subpath; t = 0, 1: raster is where it landed (already
    // scaled by 1 / (width * height) like every light-tracing splat).
    virtual void add(int s, int t, const Vec2& raster, const Color& unweighted, const Color& weighted) = 0;
};

// Techniques a later lesson adds to bidirectional path tracing (Registry<ExtraTechnique>, keyed by
// a name): bptSample calls each after its own (s, t >= 1), in the order registered, with the
// pixel sample's light subpath and rng. An extra technique decides from the scene whether it
// applies (t = 0 needs a camera whose points rays can hit: a camera model, camera.h), draws no
// number where it does not, weights what it samples by this lesson's MIS against every other
// technique, asks opt.techniqueFilter, and adds it through splat (and the recorder, if any).
using ExtraTechnique = void (*)(const Scene& scene, const Subpath& light, Rng& rng, const BptOptions& opt,
                                const SplatTarget& splat, TechniqueRecorder* recorder);

// One pixel sample: a camera subpath through `raster`, a light subpath, every (s, t), then the
// extra techniques. Returns the t >= 2 estimate for the pixel; t = 1 contributions go to splat,
// and so do the extra techniques' (t = 0). recorder may be null.
Color bptSample(const Scene& scene, const Vec2& raster, Rng& rng, const BptOptions& opt, const SplatTarget& splat,
                TechniqueRecorder* recorder);

// bptSample's techniques (s, t), t >= 1, for two subpaths traced elsewhere (the camera subpath
// through `raster`): the same connections, random numbers and weights, for a caller that keeps
// its subpaths (bptSample is cameraSubpath, lightSubpath, then this).
Color connectSubpaths(const Scene& scene, const Subpath& camera, const Subpath& light, const Vec2& raster, Rng& rng,
                      const BptOptions& opt, const SplatTarget& splat, TechniqueRecorder* recorder);

// The pruning decisions of Eq. 7.12 for this scene, one line each (empty if !opt.prune).
std::vector<std::string> bptLeftOut(const Scene& scene, const BptOptions& opt);

// Veach's pyramid: per technique images for path lengths k = 1 .. maxLength (k edges,
// s + t = k + 1), stored row by row: row k holds s = 0 .. k + 1 (techniqueIndex).
struct TechniqueImages {
    int maxLength = 0;
    std::vector<Image> unweighted, weighted;  // per technique, techniqueIndex(s, k)
    std::vector<Image> unweightedSq;          // per-sample sum of squares (variance), same order
    int spp = 0;
    SampleStats stats;  // NaN/Inf values met (counted, left out of the images)
};
inline int techniqueIndex(int s, int k) { return (k - 1) * (k + 4) / 2 + s; }  // row k holds s = 0 .. k + 1
inline int techniqueCount(int maxLength) { return techniqueIndex(0, maxLength + 1); }
// Renders spp samples per pixel with `threads` threads; images are means over the samples and
// do not depend on the number of threads (t = 1 values are added in a fixed order).
TechniqueImages renderTechniques(const Scene& scene, int maxLength, int spp, uint64_t seed, int threads,
                                 const BptOptions& opt);

// The per-technique images the pyramid command asks an integrator for (framework/integrator.h,
// Integrator::techniques): renderTechniques as rows k = 1 .. maxLength of cells s = 0 .. k + 1,
// named "s-t" and labelled "(s,t)". options(scene) gives the options (an algorithm that renders
// only some paths sets its technique filter per scene).
TechniqueRenderer bptTechniqueRenderer(std::function<BptOptions(const Scene&)> options);

}  // namespace ps
