// Lesson 5 — the adjoint BSDF: how a particle scatters. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

bool sampleAdjointBSDF(const Material& m, const Vec3& n, const Vec3& wLight, const Vec2& u, float uLobe,
                       BSDFSample& s) {
    //! TODO(05) The particle's next direction and power factor (Eq. 5.6-5.8), as lighttracer.h specifies; the smooth
    //!          dielectric by hand (README 2), reflecting when uLobe < F as framework/bsdf.cpp does. Pitfalls, README
    //!          6: the cosine of the arrival direction instead of the sampled one; an eta^2 on refraction.
    //! STUB (void)m; (void)n; (void)wLight; (void)u; (void)uLobe; (void)s;
    //! STUB return PS_TODO("lesson 05: sampleAdjointBSDF", false);
    //! BEGIN
    if (m.kind == BSDFKind::Dielectric) {
        const float cosL = glm::dot(n, wLight);
        if (cosL == 0.0f) return false;
        const bool fromOutside = cosL > 0.0f;
        const float etaFrom = fromOutside ? 1.0f : m.ior, etaTo = fromOutside ? m.ior : 1.0f;
        const Vec3 ns = fromOutside ? n : -n;
        const float cosI = std::abs(cosL);
        const float F = fresnelDielectric(cosI, etaFrom, etaTo);
        s.delta = true;
        s.weight = Color(1.0f);  // reflected or refracted, the particle keeps its power
        if (uLobe < F) {
            s.wi = reflect(wLight, ns);
            s.pdf = F;
            return true;
        }
        const float eta = etaFrom / etaTo;
        const float cosT = std::sqrt(std::max(0.0f, 1.0f - eta * eta * (1.0f - cosI * cosI)));
        s.wi = glm::normalize(-eta * wLight + (eta * cosI - cosT) * ns);
        s.pdf = 1.0f - F;
        return true;
    }
    if (!sampleBSDF(m, n, wLight, u, uLobe, Transport::Importance, s)) return false;
    if (!s.delta) s.weight = evalBSDF(m, n, s.wi, wLight) * (std::abs(glm::dot(n, s.wi)) / s.pdf);
    return true;
    //! END
}

}  // namespace ps
