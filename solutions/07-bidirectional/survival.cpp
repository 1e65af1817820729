// Lesson 7 — how long the subpaths live: the material's survival probability (Eq. 7.1a) as the
// subpaths' continuation rule, lesson 3's extension point of the walk (Eq. 3.10). Interface:
// lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include <algorithm>
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

float subpathSurvival(const Material& m) {
    //! TODO(07) q(x) of Eq. 7.1a for a vertex of material m, a probability in [0, 1] (subpathSurvival in bpt.h).
    //!          Pitfalls (README 6): the largest channel, not an average; a kind of material that loses no energy.
    //! STUB (void)m;
    //! STUB return PS_TODO("lesson 07: subpathSurvival", 1.0f);
    //! BEGIN
    if (m.kind == BSDFKind::Dielectric) return 1.0f;
    return std::min(1.0f, maxComponent(m.albedo));
    //! END
}

Continuations subpathContinuation(const Scene& scene, const WalkVertex& v, Rng& rng) {
    //! TODO(07) The continuation rule of Eq. 3.10 with q = subpathSurvival at v (Eq. 7.1a; subpathContinuation in
    //!          bpt.h). Pitfalls (README 6): the survivor's beta divided by q (Eq. 3.10's E[n] beta' = beta); the
    //!          walk's own roulette left on is a second roulette.
    //! STUB (void)scene; (void)rng;
    //! STUB const Continuations once{1, v.beta, true};
    //! STUB return PS_TODO("lesson 07: subpathContinuation", once);
    //! BEGIN
    const float q = subpathSurvival(scene.materials[v.sp.material]);
    if (q < 1.0f && !(rng.uniform() < q)) return Continuations{0, v.beta, false};
    return Continuations{1, v.beta / q, false};
    //! END
}

}  // namespace ps
