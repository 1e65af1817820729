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
    // TODO(03) One bounce (Eq. 3.4) and, if `roulette`, the roulette (Eq. 3.5) for one continuation leaving v: false
    //          if it ends there, else next as WalkStart documents it (sampler: randomWalk's comment in walk.h; random
    //          numbers' order: README 2). The survival function reads the throughput and the bounces since the walk's
    //          start, this one included (scatterings). Pitfall: a survivor divides beta and the throughput by q.
    (void)scene; (void)v; (void)beta; (void)roulette; (void)start; (void)scatter; (void)rng; (void)opt;
    (void)next;
    return PS_TODO("lesson 03: randomWalk (leaving a vertex)", false);
}

}  // namespace

void randomWalk(const Scene& scene, const WalkStart& start, BSDFSampling scatter, Rng& rng, const WalkOptions& opt,
                const WalkVisitor& visit) {
    // TODO(03) The walk of Eq. 3.3-3.5, 3.10 as randomWalk's comment in walk.h specifies it (a continuation rule's
    //          roulette = false: no roulette for its continuations); a start with more than opt.maxDepth bounces has no
    //          vertex. Pitfalls (README 6): off by one bounce at maxDepth; recursing for every bounce overflows the
    //          stack at 10^5 bounces: only a split's extra continuations may recurse.
    (void)scene; (void)start; (void)scatter; (void)rng; (void)opt; (void)visit;
    (void)PS_TODO("lesson 03: randomWalk", 0);
}

}  // namespace ps
