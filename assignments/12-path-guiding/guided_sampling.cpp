// Lesson 12 — guided sampling: the one-sample mixture of the learned guide and the BSDF, and its
// density. Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md.
#include <cmath>
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

float guidedPdf(const Material& m, const Vec3& n, const Vec3& wo, const DirectionalTree& guide, float alpha,
                const Vec3& wi) {
    // TODO(12) The mixture's density of wi per unit solid angle (Eq. 12.3; guiding.h). Pitfall (README 6):
    //          both terms carry their selection probability; the guide's density is already per steradian.
    (void)m; (void)n; (void)wo; (void)guide; (void)alpha; (void)wi;
    return PS_TODO("lesson 12: guidedPdf", 0.0f);
}

bool sampleGuided(const Material& m, const Vec3& n, const Vec3& wo, const DirectionalTree& guide, float alpha, Rng& rng,
                  BSDFSample& s) {
    // TODO(12) One direction from the mixture and its weight (Eq. 12.3, 12.4), the random numbers drawn in the
    //          order guiding.h states (the tests replay it). Pitfalls (README 6): a BSDF-sampled direction is
    //          divided by the mixture's density too; a delta lobe is never guided.
    (void)m; (void)n; (void)wo; (void)guide; (void)alpha; (void)rng; (void)s;
    return PS_TODO("lesson 12: sampleGuided", false);
}

}  // namespace ps
