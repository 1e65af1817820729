// Lesson 4 — the flux through a region S, measured from the lights. Interface:
// lessons/04-measurement/measurement.h. Equation numbers refer to lessons/04-measurement/README.md.
#include "04-measurement/measurement.h"
#include "todo.h"

namespace ps {

Color fluxParticle(const Scene& scene, const Region& S, Rng& rng) {
    // TODO(04) One particle's share of Phi_S (Eq. 4.12, 4.13), random numbers in measurement.h's order. Pitfalls: P(l)
    //          left out; a cosine at a point light or the background (README 6; light.h).
    (void)scene; (void)S; (void)rng;
    return PS_TODO("lesson 04: fluxParticle", Color(0.0f));
}

}  // namespace ps
