// Lesson 11 — progressive radiosity (Cohen, Chen, Wallace and Greenberg 1988), the classic that
// carries only L D* E paths: every quad of the scene is a patch, cut into elements of constant
// radiosity B (power per unit area leaving the surface, W/m^2; radiance B / pi); the form factor
// F_ij, the fraction of the power leaving element i that arrives at element j, is estimated by
// ray casting; and the shooting (Southwell) iteration sends each element's unshot power to every
// other element, the element with the most first. Implemented in solutions/11-classics/
// {form_factor,shooting,ambient}.cpp (reference) or assignments/11-classics/ (yours);
// lessons/11-classics/README.md derives every formula (Eq. 11.20-11.29).
//
// What radiosity needs of a scene: quads (Scene::quads) with diffuse materials, lit by quads with
// emission. Anything else (spheres, triangles and meshes, Phong, mirrors, glass, point lights, a
// background) is refused with an InputError naming it (ElementMesh, checkRadiosityScene).
// Elements are one-sided, as in the classic method: an element is the front of a piece of a quad
// (the side its normal points to); light that reaches the back of a reflecting quad is lost to
// radiosity (the integrator reports how much; none in the Cornell box, whose quads face the room).
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>
#include "integrator.h"
#include "rng.h"
#include "scene.h"

namespace ps {

// ---------------------------------------------------------------------------------------------
// The settings radiosity reads: render parameters this lesson registers (radiosity_integrator.cpp;
// framework/scene.h): `render elements N M shots S` in a scene file, `--elements NxM --shots S`
// on the command line.

// The most elements radiosity cuts a quad's edge into.
constexpr int kMaxElements = 256;
struct RadiositySettings {
    // Each quad is cut into nu x nv elements (along its edges 1-2 and 1-4), 1 .. kMaxElements each.
    int nu = 8, nv = 8;
    int shots = 256;  // shooting steps per iteration, >= 1
};
// The scene's (or the command line's) settings, the defaults above where it sets none.
RadiositySettings radiositySettings(const RenderSettings& settings);
// Sets them as render parameters (what `render elements nu nv shots S` would), for tests and tools.
void setRadiositySettings(RenderSettings& settings, const RadiositySettings& radiosity);

// ---------------------------------------------------------------------------------------------
// Elements (plumbing: radiosity_mesh.cpp).

// One element: the piece (a, b) of a quad cut into nu x nv pieces along its edges 1-2 (a) and
// 1-4 (b), by bilinear coordinates (u, v) in [a/nu, (a+1)/nu] x [b/nv, (b+1)/nv].
struct Element {
    int quad = -1;     // index into Scene::quads
    int a = 0, b = 0;  // its place in the quad's grid
    Vec3 corners[4];   // counter-clockwise seen from the front, like the quad's
    Vec3 normal;       // unit, the front's: the quad's normal (its first triangle's)
    float area = 0.0f;
    Color rho;  // reflectance: the albedo of the quad's diffuse material (0 for an emitter without one)
    Color E;    // emitted radiosity (exitance): pi Le for a quad with emission Le, else 0 (Eq. 11.20)
};

// The elements of a scene's quads, and the two ways a ray or a sample meets them.
class ElementMesh {
public:
    ElementMesh() = default;
    // Every quad of the scene cut into nu x nv elements (1 <= nu, nv <= kMaxElements). Throws
    // InputError (checkRadiosityScene) if the scene has anything radiosity does not handle.
    ElementMesh(const Scene& scene, int nu, int nv);

    int size() const { return int(elements_.size()); }
    const Element& operator[](int i) const { return elements_[size_t(i)]; }
    const std::vector<Element>& elements() const { return elements_; }
    int nu() const { return nu_; }
    int nv() const { return nv_; }
    // The elements of quad q are first(q), ..., first(q) + nu * nv - 1 (a + nu * b after first).
    int first(int q) const { return q * nu_ * nv_; }

    // A point uniformly distributed over element i (density 1 / area) for u in [0,1)^2, as a
    // surface point of the scene: p on the quad's triangle, n that triangle's normal (the
    // element's front), prim that triangle (so Scene::spawnRay and spawnRayTo work from it).
    SurfacePoint samplePoint(int i, const Vec2& u) const;
    // The element hit at surface point sp by a ray travelling in direction d; -1 if the ray
    // arrives at the back of the quad (one-sided elements) or sp is not on a quad.
    int elementAt(const SurfacePoint& sp, const Vec3& d) const;

private:
    const Scene* scene_ = nullptr;
    int nu_ = 0, nv_ = 0;
    std::vector<Element> elements_;
    std::vector<int> quadOfPrim_;  // Scene::prims index -> quad index, -1 if not a quad's
};

// Throws InputError if the scene has what radiosity cannot handle, naming the first such thing:
// spheres, triangles that are not a quad's (triangle and mesh statements), quads with a material
// that is not diffuse, concave quads, point lights, a background light.
void checkRadiosityScene(const Scene& scene);

// ---------------------------------------------------------------------------------------------
// (a) Form factors by ray casting (form_factor.cpp; Eq. 11.22-11.26).

// The unoccluded form factor from a point x (unit normal nx) to a small element of area areaY
// around y (unit normal ny), Eq. 11.23:
//     g = areaY cos+(theta_x) cos+(theta_y) / (pi r^2),   r = |y - x|,
// cos+(theta_x) = max(0, nx . (y - x) / r), cos+(theta_y) = max(0, ny . (x - y) / r): 0 when
// either faces away from the other (one-sided elements). 0 when r = 0.
float pointFormFactor(const Vec3& x, const Vec3& nx, const Vec3& y, const Vec3& ny, float areaY);

// F_ij, the form factor from element i to element j, estimated with `samples` samples (Eq.
// 11.26), each one point x uniform on element i (mesh.samplePoint) and two techniques
// combined by the balance heuristic:
//   area:   a point y uniform on element j, g = pointFormFactor(x, n_x, y, n_y, A_j), and the
//           visibility V(x, y) by a shadow ray (Scene::spawnRayTo, occluded): adds V g / (1 + g);
//   cosine: a cosine-distributed direction around n_x (lesson 1's warp), traced from x
//           (Scene::spawnRay, intersect); if its first hit is on element j (mesh.elementAt), at
//           y': adds g' / (1 + g') with g' = pointFormFactor(x, n_x, y', n_y', A_j).
// The estimate is the sum over the samples divided by `samples`. Each sample adds at most 2, so
// its variance is bounded even for elements that share an edge, where area sampling alone has
// infinite variance (Eq. 11.25). Numbers drawn per sample, in this order: x (2), y (2), the
// direction (2).
float formFactor(const Scene& scene, const ElementMesh& mesh, int i, int j, int samples, Rng& rng);

// Samples per form factor in the integrator: at least kFormFactorSamples, and at least
// kRowSamples over a row of the N elements' form factors (ceil(kRowSamples / N) each), so that a
// coarse mesh, whose few large elements share long edges (the noisiest pairs, Eq. 11.25), is
// not noisier than a fine one.
constexpr int kFormFactorSamples = 16;
constexpr int kRowSamples = 16384;
inline int formFactorSamples(int elements) {
    return std::max(kFormFactorSamples, (kRowSamples + std::max(elements, 1) - 1) / std::max(elements, 1));
}

// Row i of the form factors (plumbing: radiosity_integrator.cpp): F[j] = F_ij for every element
// j, each formFactor(..., formFactorSamples(N), rng) with rng = taskRng(seed, i, j), in the
// framework's task loop: the same numbers for any number of threads, and the same row every time
// element i shoots. F_ij = 0 without a ray where it is 0 exactly: j on i's own quad (a quad is
// flat), or j wholly behind i's plane, or i wholly behind j's. `back` is the fraction of the
// power leaving i that arrives at the back of a reflecting quad, which one-sided elements lose
// (estimated with 4 kFormFactorSamples cosine rays from i). stats counts the rays. With a
// `stop` that says true while the row is computed (the render's time is up), the row is
// abandoned: F comes back empty.
struct FormFactorRow {
    std::vector<float> F;
    float back = 0.0f;
};
FormFactorRow formFactorRow(const Scene& scene, const ElementMesh& mesh, int i, uint64_t seed, SampleStats& stats,
                            const Integrator* stop = nullptr);

// ---------------------------------------------------------------------------------------------
// (b) Progressive refinement: the shooting iteration (shooting.cpp; Eq. 11.27, 11.28).

struct RadiositySolution {
    std::vector<Color> B;       // radiosity of every element (per channel)
    std::vector<Color> unshot;  // Delta B: the part of B that element has not shot yet
    int shots = 0;              // shooting steps made
};

// The solution before the first shot (Eq. 11.27): B_i = E_i and unshot_i = E_i for every element.
RadiositySolution startRadiosity(const ElementMesh& mesh);

// The shooter (Eq. 11.28): the element with the most unshot power, unshot_i A_i summed over the
// three channels; the first of equal ones; -1 if no element has any (all unshot black).
int chooseShooter(const ElementMesh& mesh, const RadiositySolution& s);

// One shooting step from element i with its row of form factors, F[j] = F_ij (Eq. 11.28): the
// unshot radiosity dB = unshot_i is taken (unshot_i = 0), and every element j receives
//     dB_j = rho_j dB F_ij A_i / A_j       (reciprocity: F_ij A_i / A_j = F_ji),
// added to both B_j and unshot_j; then shots + 1.
void shoot(const ElementMesh& mesh, RadiositySolution& s, int i, const std::vector<float>& F);

// The fraction of the emitted power not shot yet (the iteration's residual): sum over elements
// and channels of unshot_i A_i, divided by the same sum of E_i A_i (0 without emission).
double unshotFraction(const ElementMesh& mesh, const RadiositySolution& s);

// The integrator stops shooting once unshotFraction is below this.
constexpr double kStopResidual = 1e-4;

// ---------------------------------------------------------------------------------------------
// (c) The ambient term for display (ambient.cpp; Eq. 11.29, Cohen et al. 1988, section 4): the
// unshot power as if spread evenly over all elements and reflected infinitely often,
//     ambient = R sum_j unshot_j A_j / sum_j A_j,   R = 1 / (1 - rho_avg),
//     rho_avg = sum_j rho_j A_j / sum_j A_j        (per channel),
// shown as B_i + rho_i ambient. Black without elements.
Color ambientRadiosity(const ElementMesh& mesh, const RadiositySolution& s);

// ---------------------------------------------------------------------------------------------
// Patch averages (radiosity_patches.cpp): the mean radiance leaving each quad's front,
// (1 / A_q) integral over the quad of L_o dA, which the tests and figures compare.

// Of a radiosity solution: sum_e B_e A_e / (pi sum_e A_e) over the quad's elements (black if the
// solution has not started).
std::vector<Color> patchRadiance(const ElementMesh& mesh, const RadiositySolution& s);

// Estimated by lesson 3's path tracer (LiMIS, at most maxDepth bounces): `samples` points
// uniform on each quad (by area), each seen along -n by a ray from just off its front (a diffuse
// surface leaves the same radiance in every direction), in the framework's task loop (the same
// for any number of threads). Mean and standard error of the mean per channel.
struct PatchEstimate {
    DColor mean, stdError;
};
std::vector<PatchEstimate> patchRadiancePT(const Scene& scene, int samples, int maxDepth, uint64_t seed);

// ---------------------------------------------------------------------------------------------
// The integrators (radiosity_integrator.cpp): "radiosity" shows each element's radiance B / pi,
// flat; "radiosity-ambient" adds the ambient term (display only: the solution is the same).
// Iteration k makes radiositySettings(...).shots shooting steps (until the residual is below
// kStopResidual) and renders the solution so far; the film keeps only the latest image.
class RadiosityIntegrator : public Integrator {
public:
    explicit RadiosityIntegrator(bool ambient = false) : ambient_(ambient) {}
    void prepare(const Scene& scene) override;
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override;
    std::vector<std::string> report() const override;

    // Shooting steps until `shots` more are made or the residual is below kStopResidual, or the
    // render's time is up (timeIsUp: checked before each step and while a row of form factors
    // is computed; a row not finished is dropped, so every step made is whole).
    void shootSteps(const Scene& scene, int shots, uint64_t seed, SampleStats& stats);
    // The radiance an element shows: B / pi, plus rho ambient / pi with the ambient term.
    Color radiance(int element) const;
    const ElementMesh& mesh() const { return mesh_; }
    const RadiositySolution& solution() const { return solution_; }

private:
    bool ambient_ = false;
    ElementMesh mesh_;
    RadiositySolution solution_;
    Color ambientTerm_;
    std::vector<FormFactorRow> rows_;  // the rows computed so far (empty: not yet, or not kept)
    size_t keptFloats_ = 0;
    uint64_t rowsComputed_ = 0;
    int cutIterations_ = 0;   // iterations that ended early at the time budget
    double backPower_ = 0.0;  // power shot onto the backs of reflecting quads (lost)
    double shotPower_ = 0.0;  // power shot in all
};

// Sub-pixel samples per pixel and axis of the radiosity images (fixed positions: an image of a
// given solution is the same every time).
constexpr int kRadiosityPixelSamples = 3;

}  // namespace ps
