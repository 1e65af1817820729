// Lesson 3 — the random walk, shared by the three estimators (random_walk.cpp, next_event.cpp,
// path_mis.cpp), by lesson 5's light walk and by every later algorithm that follows paths.
// Interface: lessons/03-path-tracing/walk.h. Equation numbers refer to lessons/03-path-tracing/README.md.
#include "03-path-tracing/walk.h"
#include "todo.h"

namespace ps {

namespace {

// One continuation leaving the visited vertex v with throughput beta (and `throughput`, what the
// survival function reads, from `start`), with Russian roulette after the bounce if `roulette`:
// the next ray and what it carries, in `next`. False if the continuation ends at v.
[[maybe_unused]] bool leave(const Scene& scene, const WalkVertex& v, Color beta, bool roulette, const WalkStart& start,
                            BSDFSampling scatter, Rng& rng, const WalkOptions& opt, WalkStart& next) {
    // TODO(03) One bounce of Eq. 3.4 and the roulette of Eq. 3.5 for one continuation leaving v
    //          with throughput beta: false if it ends at v (no direction, a black throughput,
    //          the roulette), else next holds the ray leaving v and what its first vertex shows.
    //          The direction: the walk's own BSDF sampling `scatter` at a delta material or when
    //          the options have no direction sampler, else the sampler's. The survival function
    //          reads the throughput since the walk's start and the bounces since then, this one
    //          included; no roulette when `roulette` is false (the rule decided survival).
    //          Pitfalls: a survivor divides beta AND the throughput by q. The tests replay the
    //          random numbers: the direction's u = rng.uniform2() before uLobe = rng.uniform(),
    //          into variables (C++ evaluates a call's arguments in no fixed order), the
    //          roulette's only when q < 1.
    (void)scene; (void)v; (void)beta; (void)roulette; (void)start; (void)scatter; (void)rng; (void)opt;
    (void)next;
    return PS_TODO("lesson 03: randomWalk (leaving a vertex)", false);
}

}  // namespace

void randomWalk(const Scene& scene, const WalkStart& start, BSDFSampling scatter, Rng& rng, const WalkOptions& opt,
                const WalkVisitor& visit) {
    // TODO(03) The walk of Eq. 3.3-3.5, 3.10 from start.ray. At each vertex: intersect, fill a
    //          WalkVertex from what the walk carries (start's fields; its fields say what each
    //          one holds: the escape is a vertex too) and call visit; the walk ends if it returns
    //          false, on a miss, or at bounces == opt.maxDepth (Eq. 3.3: the vertex with maxDepth
    //          bounces is visited, no bounce after it). Else the continuations: opt.continuation's
    //          (if set), else one with the vertex's beta. Each leaves the vertex (leave(), above,
    //          with the walk's roulette unless the rule said roulette = false)
    //          and is followed to its very end before the next one leaves (Eq. 3.10, depth first):
    //          all but the last as a walk of their own, the last by this loop. A start with more
    //          than opt.maxDepth bounces has no vertex.
    //          Pitfall: recursion for every bounce overflows the stack on a walk of 10^5 bounces:
    //          only the extra continuations of a split may recurse.
    (void)scene; (void)start; (void)scatter; (void)rng; (void)opt; (void)visit;
    (void)PS_TODO("lesson 03: randomWalk", 0);
}

}  // namespace ps
