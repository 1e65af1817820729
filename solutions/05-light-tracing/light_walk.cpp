// Lesson 5 — the particle's random walk: lesson 3's walk, started on a light. Shared by the light
// tracer (light_path.cpp) and by lesson 7's light subpath. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

void lightWalk(const Scene& scene, Rng& rng, const WalkOptions& opt, const LightWalkVisitor& visit) {
    //! TODO(05) The particle's walk (Eq. 5.1, 5.2, 5.6-5.8): start it with startLightPath
    //!          (scene, uLight, uPos, uDir), drawn into variables in that order (rng.uniform(),
    //!          rng.uniform2(), rng.uniform2(): a call's arguments have no order); nothing if
    //!          not valid. Visit y0
    //!          (a WalkVertex with bounces 0, hit, sp = start.y0, beta = start.beta), then lesson
    //!          3's randomWalk from a WalkStart along start.ray (its fields say what the particle's
    //!          first hit y1 shows), scattering with sampleAdjointBSDF and the options given, with
    //!          a visitor that hands each surface the particle hits, and the start, to `visit`.
    //!          Pitfalls: bounces count the surfaces hit (y1 has 1), and a miss is no vertex of
    //!          a light path; the roulette follows the throughput since y0, which starts at 1,
    //!          not at start.beta (whose scale is the light's power).
    //! STUB (void)scene; (void)rng; (void)opt; (void)visit;
    //! STUB (void)PS_TODO("lesson 05: lightWalk", 0);
    //! BEGIN
    // Named, in this order: C++ evaluates a call's arguments in no fixed order.
    const float uLight = rng.uniform();
    const Vec2 uPos = rng.uniform2();
    const Vec2 uDir = rng.uniform2();
    const LightPathStart start = startLightPath(scene, uLight, uPos, uDir);
    if (!start.valid) return;
    WalkVertex y0;
    y0.hit = true;
    y0.sp = start.y0;
    y0.beta = start.beta;
    y0.specular = false;
    if (!visit(y0, start)) return;
    WalkStart first;
    first.ray = start.ray;
    first.beta = start.beta;
    first.bounces = 1;
    first.specular = false;
    first.pPrev = start.y0.p;
    randomWalk(scene, first, sampleAdjointBSDF, rng, opt,
               [&](const WalkVertex& v) { return v.hit && visit(v, start); });
    //! END
}

}  // namespace ps
