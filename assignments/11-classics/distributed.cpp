// Lesson 11 — distributed ray tracing: lens, area lights and glossy lobes sampled, mirrors and
// glass followed, no diffuse interreflection: lesson 3's path tracer with another visitor.
// Interface: lessons/11-classics/distributed.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/distributed.h"
#include "todo.h"

namespace ps {

Color LiDistributed(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth) {
    // TODO(11) Eq. 11.19 as a visitor of lesson 3's camera walk, without Russian roulette
    //          (alwaysSurvive: the walk ends only where the visitor or maxDepth says). At each
    //          vertex, in this order: the emission the walk found, weighted as in lesson 3's
    //          pt (misEmission); then at a glossy, mirror or glass vertex lesson 3's
    //          MIS-weighted light sample (misLightSample) and the walk goes on; at a diffuse one
    //          a light sample (lesson 2's sampleDirectLight(scene, sp, wo, uLight, uPoint),
    //          uLight = rng.uniform() drawn before uPoint = rng.uniform2()) with weight 1, if the
    //          path may still have a bounce, and the walk ends there.
    //          Pitfalls: at a diffuse point no BSDF sample competes with the light sample (an MIS
    //          weight there loses light); a miss ends the walk.
    (void)scene; (void)cameraRay; (void)rng; (void)maxDepth;
    return PS_TODO("lesson 11: LiDistributed", Color(0.0f));
}

}  // namespace ps
