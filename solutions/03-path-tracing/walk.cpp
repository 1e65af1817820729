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
    //! TODO(03) One bounce (Eq. 3.4) and, if `roulette`, the roulette (Eq. 3.5) for one continuation leaving v: false
    //!          if it ends there, else next as WalkStart documents it (sampler: randomWalk's comment in walk.h; random
    //!          numbers' order: README 2). The survival function reads the throughput and the bounces since the walk's
    //!          start, this one included (scatterings). Pitfall: a survivor divides beta and the throughput by q.
    //! STUB (void)scene; (void)v; (void)beta; (void)roulette; (void)start; (void)scatter; (void)rng; (void)opt;
    //! STUB (void)next;
    //! STUB return PS_TODO("lesson 03: randomWalk (leaving a vertex)", false);
    //! BEGIN
    const Material& m = scene.materials[v.sp.material];
    BSDFSample s;
    bool sampled = false;
    if (m.isDelta() || !opt.sampler) {
        // Named, in this order: C++ evaluates a call's arguments in no fixed order.
        const Vec2 u = rng.uniform2();
        const float uLobe = rng.uniform();
        sampled = scatter(m, v.sp.n, v.wo, u, uLobe, s);
    } else {
        sampled = opt.sampler->sample(scene, v, rng, s);
    }
    if (!sampled) return false;
    Color throughput = start.throughput;
    beta *= s.weight;
    throughput *= s.weight;
    if (isBlack(beta)) return false;
    const float q = roulette ? opt.survival(throughput, start.scatterings + 1) : 1.0f;
    if (q < 1.0f) {
        if (rng.uniform() >= q) return false;
        beta /= q;
        throughput /= q;
    }
    next.ray = scene.spawnRay(v.sp, s.wi);
    next.beta = beta;
    next.throughput = throughput;
    next.bounces = v.bounces + 1;
    next.scatterings = start.scatterings + 1;
    next.specular = s.delta;
    next.pdfPrev = s.pdf;
    next.pPrev = v.sp.p;
    return true;
    //! END
}

}  // namespace

void randomWalk(const Scene& scene, const WalkStart& start, BSDFSampling scatter, Rng& rng, const WalkOptions& opt,
                const WalkVisitor& visit) {
    //! TODO(03) The walk of Eq. 3.3-3.5, 3.10 as randomWalk's comment in walk.h specifies it (a continuation rule's
    //!          roulette = false: no roulette for its continuations); a start with more than opt.maxDepth bounces has no
    //!          vertex. Pitfalls (README 6): off by one bounce at maxDepth; recursing for every bounce overflows the
    //!          stack at 10^5 bounces: only a split's extra continuations may recurse.
    //! STUB (void)scene; (void)start; (void)scatter; (void)rng; (void)opt; (void)visit;
    //! STUB (void)PS_TODO("lesson 03: randomWalk", 0);
    //! BEGIN
    WalkStart at = start;
    if (at.bounces > opt.maxDepth) return;
    for (;;) {
        WalkVertex v;
        Ray ray = at.ray;
        v.hit = scene.intersect(ray, v.sp);
        v.bounces = at.bounces;
        v.wo = -ray.d;
        v.distance = ray.tMax;
        v.beta = at.beta;
        v.specular = at.specular;
        v.pdfPrev = at.pdfPrev;
        v.pPrev = at.pPrev;
        v.sampler = opt.sampler;
        if (!visit(v) || !v.hit || v.bounces == opt.maxDepth) return;
        const Continuations c = opt.continuation ? opt.continuation(v, rng) : Continuations{1, v.beta};
        WalkStart next;
        for (int i = 1; i < c.n; ++i)
            if (leave(scene, v, c.beta, c.roulette, at, scatter, rng, opt, next))
                randomWalk(scene, next, scatter, rng, opt, visit);
        if (c.n < 1 || !leave(scene, v, c.beta, c.roulette, at, scatter, rng, opt, next)) return;
        at = next;
    }
    //! END
}

}  // namespace ps
