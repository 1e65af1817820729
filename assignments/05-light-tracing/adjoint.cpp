// Lesson 5 — the adjoint BSDF: how a particle scatters. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

bool sampleAdjointBSDF(const Material& m, const Vec3& n, const Vec3& wLight, const Vec2& u, float uLobe,
                       BSDFSample& s) {
    // TODO(05) Write the smooth dielectric yourself (Eq. 5.8); do not call sampleBSDF for it:
    //          cosL = dot(n, wLight), false if 0; the particle comes from the outside (index 1)
    //          if cosL > 0, else from the inside (m.ior); ns = n flipped to wLight's side;
    //          F = fresnelDielectric(|cosL|, etaFrom, etaTo). With probability F (uLobe < F)
    //          reflect: s.wi = reflect(wLight, ns), s.pdf = F; else refract by Snell's law
    //          (eta = etaFrom / etaTo, cosT = sqrt(1 - eta^2 (1 - cosL^2)),
    //          s.wi = normalize(-eta wLight + (eta |cosL| - cosT) ns)), s.pdf = 1 - F. Either
    //          way the power is kept: s.weight = 1, s.delta = true.
    //          Every other material (Eq. 5.6, 5.7): the direction from
    //          sampleBSDF(m, n, wLight, u, uLobe, Transport::Importance, s); then, unless
    //          s.delta, recompute s.weight = f(wLight -> s.wi) |cos(theta_wi)| / s.pdf with the
    //          BSDF's arguments swapped: evalBSDF(m, n, s.wi, wLight).
    (void)m; (void)n; (void)wLight; (void)u; (void)uLobe; (void)s;
    return PS_TODO("lesson 05: sampleAdjointBSDF", false);
}

}  // namespace ps
