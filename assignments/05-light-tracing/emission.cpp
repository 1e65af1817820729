// Lesson 5 — the start of a light path: emission sampling. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

LightPathStart startLightPath(const Scene& scene, float uLight, const Vec2& uPos, const Vec2& uDir) {
    // TODO(05) The first vertex y0, its density P(l) p_A and the particle's power beta_1 leaving it (Eq. 5.2), started
    //          as lesson 4's particles (Eq. 4.13). Pitfall: a cosine at a point light or the background.
    (void)scene; (void)uLight; (void)uPos; (void)uDir;
    return PS_TODO("lesson 05: startLightPath", LightPathStart());
}

}  // namespace ps
