// Lesson 11 — distributed ray tracing: lens, area lights and glossy lobes sampled, mirrors and
// glass followed, no diffuse interreflection: lesson 3's path tracer with another visitor.
// Interface: lessons/11-classics/distributed.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/distributed.h"
#include "todo.h"

namespace ps {

Color LiDistributed(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    // TODO(11) The radiance of the paths of Eq. 11.19 along the camera ray, as distributed.h states them, as a visitor
    //          of lesson 3's camera walk without roulette and with lesson 3's MIS where a G vertex competes. The tests
    //          replay the diffuse vertex's light sample (within maxDepth): uLight drawn before uPoint. Pitfalls
    //          (README 6): at a D vertex the light sample has weight 1 and the walk ends; a miss ends the walk.
    (void)scene; (void)cameraRay; (void)rng; (void)maxDepth;
    return PS_TODO("lesson 11: LiDistributed", Color(0.0f));
}

}  // namespace ps
