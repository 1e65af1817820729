// Lesson 11 — Whitted's recursion: mirrors, both branches of glass, point lights and the
// ambient term. Interface: lessons/11-classics/whitted.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/whitted.h"
#include "todo.h"

namespace ps {

Color LiWhitted(const Scene& scene, const Ray& ray, int bounces, const WhittedOptions& opt) {
    // TODO(11) Whitted's recursion, Eq. 11.9, as LiWhitted in whitted.h states it. Pitfalls (README 6): a surface
    //          reached after maxDepth bounces only emits; the ambient term only where shaded and only what opt asks.
    (void)scene; (void)ray; (void)bounces; (void)opt;
    return PS_TODO("lesson 11: LiWhitted", Color(0.0f));
}

}  // namespace ps
