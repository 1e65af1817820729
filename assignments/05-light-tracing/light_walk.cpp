// Lesson 5 — the particle's random walk, shared by the light tracer (light_path.cpp) and by
// lesson 7's light subpath. Interface: lessons/05-light-tracing/lighttracer.h. Equation numbers
// refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

void lightWalk(const Scene& scene, Rng& rng, int maxDepth, const LightWalkVisitor& visit, SurvivalFunction survival) {
    // TODO(05) The particle's walk (Eq. 5.1, 5.2, 5.6-5.8): start it with startLightPath
    //          (scene, uLight, uPos, uDir) (rng.uniform(), rng.uniform2(), rng.uniform2());
    //          nothing if not valid. Visit y0 (bounces 0), then for bounces = 1 .. maxDepth:
    //          intersect (a miss ends the walk, unvisited), visit (false ends it), and unless
    //          bounces == maxDepth scatter with sampleAdjointBSDF(material, n, wLight, u, uLobe,
    //          s) (rng.uniform2(), rng.uniform()) (end if it fails or beta turns black) and play
    //          Russian roulette as in lesson 3 (Eq. 3.5), its number drawn only when q < 1. A
    //          LightWalkVertex's fields say what it holds.
    //          Pitfalls: q = survival(throughput, bounces) (the function passed in: lesson 3's
    //          survivalProbability unless the caller gives another) follows the product of the
    //          scattering weights alone (start at 1, not at start.beta, whose scale is the
    //          light's power); a survivor divides both beta and throughput by q. The tests
    //          replay the random numbers: draw them into variables, left to right as written
    //          (C++ evaluates a call's arguments in no fixed order).
    (void)scene; (void)rng; (void)maxDepth; (void)visit; (void)survival;
    (void)PS_TODO("lesson 05: lightWalk", 0);
}

}  // namespace ps
