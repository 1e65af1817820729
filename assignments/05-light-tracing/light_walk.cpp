// Lesson 5 — the particle's random walk: lesson 3's walk, started on a light. Shared by the light
// tracer (light_path.cpp) and by lesson 7's light subpath. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

void lightWalk(const Scene& scene, Rng& rng, const WalkOptions& opt, const LightWalkVisitor& visit) {
    // TODO(05) The particle's walk (Eq. 5.1, 5.2, 5.6-5.8) as lighttracer.h specifies it, its random numbers in that
    //          order (README 2). Pitfalls: bounces count the surfaces hit (y1 has 1) and a miss is no vertex; the
    //          roulette reads the throughput since y0, which starts at 1, not start.beta (README 6).
    (void)scene; (void)rng; (void)opt; (void)visit;
    (void)PS_TODO("lesson 05: lightWalk", 0);
}

}  // namespace ps
