// Lesson 12 — guided sampling: the one-sample mixture of the learned guide and the BSDF, and its
// density. Interface: lessons/12-path-guiding/guiding.h. Equation numbers refer to
// lessons/12-path-guiding/README.md.
#include <cmath>
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

float guidedPdf(const Material& m, const Vec3& n, const Vec3& wo, const DirectionalTree& guide, float alpha,
                const Vec3& wi) {
    //! TODO(12) The mixture's density of wi per unit solid angle (Eq. 12.3; guiding.h). Pitfall (README 6):
    //!          both terms carry their selection probability; the guide's density is already per steradian.
    //! STUB (void)m; (void)n; (void)wo; (void)guide; (void)alpha; (void)wi;
    //! STUB return PS_TODO("lesson 12: guidedPdf", 0.0f);
    //! BEGIN
    return alpha * guide.pdf(wi) + (1.0f - alpha) * pdfBSDF(m, n, wo, wi);
    //! END
}

bool sampleGuided(const Material& m, const Vec3& n, const Vec3& wo, const DirectionalTree& guide, float alpha, Rng& rng,
                  BSDFSample& s) {
    //! TODO(12) One direction from the mixture and its weight (Eq. 12.3, 12.4), the random numbers drawn in the
    //!          order guiding.h states (the tests replay it). Pitfalls (README 6): a BSDF-sampled direction is
    //!          divided by the mixture's density too; a delta lobe is never guided.
    //! STUB (void)m; (void)n; (void)wo; (void)guide; (void)alpha; (void)rng; (void)s;
    //! STUB return PS_TODO("lesson 12: sampleGuided", false);
    //! BEGIN
    if (m.isDelta()) {
        const Vec2 u = rng.uniform2();  // drawn in this order, into variables (lesson 3)
        const float uLobe = rng.uniform();
        return sampleBSDF(m, n, wo, u, uLobe, Transport::Radiance, s);
    }
    const float choose = rng.uniform();
    Vec3 wi;
    if (choose < alpha) {
        wi = guide.sample(rng.uniform2());
    } else {
        BSDFSample b;
        const Vec2 u = rng.uniform2();
        const float uLobe = rng.uniform();
        if (!sampleBSDF(m, n, wo, u, uLobe, Transport::Radiance, b)) return false;
        wi = b.wi;
    }
    const Color f = evalBSDF(m, n, wo, wi);
    if (isBlack(f)) return false;
    s.wi = wi;
    s.pdf = guidedPdf(m, n, wo, guide, alpha, wi);
    if (!(s.pdf > 0.0f)) return false;
    s.weight = f * (std::abs(dot(n, wi)) / s.pdf);
    s.delta = false;
    return true;
    //! END
}

}  // namespace ps
