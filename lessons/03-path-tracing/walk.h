// Lesson 3's random walk (Eq. 3.3-3.5, 3.10): the one loop that builds every path of the course.
// A walk follows a ray, shows every vertex it reaches to a visitor, and goes on from it by
// sampling a direction, with Russian roulette after each bounce; a continuation rule may let it
// go on from a vertex more than once (splitting) or not at all (roulette at the vertex). Lesson
// 3's camera walk (cameraWalk) and lesson 5's light walk are this one walk, started differently.
// Implemented in solutions/03-path-tracing/walk.cpp (reference) or
// assignments/03-path-tracing/walk.cpp (yours); lessons/03-path-tracing/README.md derives it.
//
// Extension points (WalkOptions): the survival function (Russian roulette), the direction
// sampler (how the walk leaves a non-delta vertex; BSDF sampling by default) and the
// continuation rule (splitting and roulette at a vertex). An algorithm that samples differently
// sets them; the walk, its visitors and lesson 3's MIS stay the same.
#pragma once
#include <functional>
#include "scene.h"

namespace ps {

// Russian roulette (Eq. 3.5): never before a path has made kRouletteStartBounces bounces; from
// then on it survives each bounce with probability min(1, max component of its throughput),
// but never less than kRouletteMinSurvival (a path that survives is divided by the
// probability: a floor keeps that factor <= 20).
constexpr int kRouletteStartBounces = 3;
constexpr float kRouletteMinSurvival = 0.05f;

// The probability that a path with throughput beta, after `bounces` bounces, goes on (Eq. 3.5).
float survivalProbability(const Color& beta, int bounces);

// A survival function that never ends a walk (q = 1): no Russian roulette.
float alwaysSurvive(const Color& throughput, int bounces);

struct DirectionSampler;

// One vertex of a walk, as the walk shows it to its visitor. The camera walk's x_k and the light
// walk's y_k are this type (lesson 5's light walk also hands its visitor the path's start).
struct WalkVertex {
    int bounces = 0;        // the camera walk's k, the bounces made before reaching x_k: 0 = the camera
                            // ray's hit (Eq. 3.3); the light walk's k: y_k is the k-th surface the
                            // particle hits, y_0 on the light
    bool hit = false;       // false: the ray left the scene (sp is not set); the walk ends here
    SurfacePoint sp;        // the surface point hit
    Vec3 wo;                // unit, back along the ray that arrived (-ray.d): towards the previous
                            // vertex (omega_o,k of Eq. 3.4)
    float distance = kInf;  // the length of that ray: the distance from the previous vertex (kInf at a miss)
    Color beta;             // the throughput beta_k of the path up to here (Eq. 3.4) times the
                            // walk's start (1 for the camera walk), divided by every survival
                            // probability so far (Eq. 3.5) and by every continuation rule's q (Eq. 3.10)
    bool specular = true;   // the bounce into this vertex was a delta sample (BSDFSample::delta);
                            // true at the camera walk's first vertex (the camera ray)
    float pdfPrev = 0.0f;   // solid-angle pdf of the direction sample that led here (0 where no
                            // sample did: the camera ray, the light's first ray)
    Vec3 pPrev;             // the previous vertex's position sp.p (0 where there is none)
    // How the walk leaves this vertex at a non-delta material: its direction sampler (nullptr:
    // BSDF sampling). pdfWalk reads it, so that MIS weights use the walk's own density.
    const DirectionSampler* sampler = nullptr;
};

// The direction sampler: how a walk picks the direction it leaves a NON-delta vertex in, and the
// density it picks it with, side by side (a delta BSDF is always sampled by the walk itself).
// The walk's default is BSDF sampling; a sampler is a walk's extension point, for a density that
// knows more than the BSDF (a mixture with a learned distribution, say).
struct DirectionSampler {
    virtual ~DirectionSampler() = default;
    // A direction s.wi at v with s.weight = f |cos theta| / s.pdf (f in the walk's transport: the
    // camera walk's f(wo, wi), the light walk's adjoint), s.pdf = pdf(scene, v, s.wi), s.delta
    // false; its random numbers from rng. False if no direction could be sampled.
    virtual bool sample(const Scene& scene, const WalkVertex& v, Rng& rng, BSDFSample& s) const = 0;
    // The solid-angle density with which sample() picks wi at v.
    virtual float pdf(const Scene& scene, const WalkVertex& v, const Vec3& wi) const = 0;
};

// The walk's own BSDF sampling at a vertex with normal n, wo towards the previous vertex: u picks
// the direction, uLobe the lobe (the camera walk: sampleBSDF with Transport::Radiance; lesson 5's
// light walk: its adjoint BSDF).
using BSDFSampling = bool (*)(const Material& m, const Vec3& n, const Vec3& wo, const Vec2& u, float uLobe,
                              BSDFSample& s);

// The probability that a walk goes on after a bounce (Russian roulette, Eq. 3.5), from its
// throughput since the walk's start (the product of the direction samples' weights, each survivor
// divided by its q) and the bounces it has made since its start, that one included.
using SurvivalFunction = float (*)(const Color& throughput, int bounces);

// How a walk goes on from a vertex: n continuations, each with throughput beta (Eq. 3.10), and
// whether the walk's own Russian roulette (WalkOptions::survival) still plays after each of their
// bounces: false where the rule has decided survival at the vertex itself (roulette and splitting
// by an estimate of what the path will bring), true where it left the decision to the walk.
struct Continuations {
    int n = 0;
    Color beta;
    bool roulette = true;
};

// The continuation rule: asked at every vertex the walk may go on from (hit, visited with true,
// fewer than maxDepth bounces), before any direction is sampled there; it may draw numbers from
// rng. Unbiased when E[n] beta' = v.beta (Eq. 3.10): n drawn with expectation q, beta' = beta / q
// (q < 1: roulette at the vertex, q > 1: splitting).
using ContinuationRule = std::function<Continuations(const WalkVertex& v, Rng& rng)>;

// What to do at a vertex; return false to end the walk (this branch of it) there. The walk calls
// it right after the intersection, so it may draw numbers from the walk's rng (a light sample).
using WalkVisitor = std::function<bool(const WalkVertex&)>;

// How a walk goes on: {maxDepth} is a plain walk, {maxDepth, survival} one with its own roulette;
// set the other fields by name.
struct WalkOptions {
    WalkOptions(int maxDepth_ = 0, SurvivalFunction survival_ = survivalProbability)
        : maxDepth(maxDepth_), survival(survival_) {}
    int maxDepth = 0;  // the vertex with maxDepth bounces is the last one (Eq. 3.3)
    // Russian roulette after each bounce (Eq. 3.5): q = survival(throughput, bounces).
    SurvivalFunction survival = survivalProbability;
    // How the walk leaves a non-delta vertex (nullptr: the walk's own BSDF sampling).
    const DirectionSampler* sampler = nullptr;
    // How often it goes on from a vertex (empty: once, with the vertex's beta).
    ContinuationRule continuation;
};

// Where a walk (or one branch of it) starts: the ray it follows and what the walk carries along
// that ray, which its first vertex shows (WalkVertex's fields of the same names).
struct WalkStart {
    Ray ray;
    Color beta = Color(1.0f);
    Color throughput = Color(1.0f);  // what the survival function reads: beta without the start's
                                     // own scale (and without a continuation rule's 1/q)
    int bounces = 0;                 // the first vertex's
    int scatterings = 0;             // the bounces made since the walk's start
    bool specular = true;
    float pdfPrev = 0.0f;
    Vec3 pPrev = Vec3(0.0f);
};

// The random walk (Eq. 3.3-3.5, 3.10): from start.ray, at every vertex x_k in order (the escape
// included: a vertex with hit = false): fill a WalkVertex and visit it; end after the visitor
// says so, after a miss, or at bounces == opt.maxDepth. Else ask opt.continuation for the
// continuations (none: one, with beta); each samples a direction at x_k (scatter at a delta
// material or without opt.sampler, else opt.sampler), multiplies its throughput by the sample's
// weight (it ends if that fails or is black), plays Russian roulette with opt.survival (unless the
// rule's continuations say roulette = false), and is followed to its very end before the next
// continuation samples (depth first).
void randomWalk(const Scene& scene, const WalkStart& start, BSDFSampling scatter, Rng& rng, const WalkOptions& opt,
                const WalkVisitor& visit);

// The random walk from the camera (plumbing, walks.cpp): randomWalk from `ray` with beta 1 and
// BSDF sampling in Transport::Radiance (Eq. 3.3-3.5). Lesson 7's camera subpath is this walk too.
void cameraWalk(const Scene& scene, const Ray& ray, Rng& rng, const WalkOptions& opt, const WalkVisitor& visit);

// The camera walk resumed in the middle of a camera path (plumbing, walks.cpp): randomWalk from
// `start` (its ray, beta, bounces, ...) with the camera walk's BSDF sampling. For an algorithm
// that follows a ray of its own from a camera vertex with the walk's rules (lesson 8's final
// gather: start.bounces is the gather ray's first vertex's k, start.beta the weight it carries).
void cameraWalk(const Scene& scene, const WalkStart& start, Rng& rng, const WalkOptions& opt, const WalkVisitor& visit);

// The solid-angle density with which the walk leaves the non-delta vertex v towards wi: its
// direction sampler's pdf, or pdfBSDF (plumbing, walks.cpp).
float pdfWalk(const Scene& scene, const WalkVertex& v, const Vec3& wi);

}  // namespace ps
