// Lesson 11 — the two branches of glass in Whitted's recursion: reflection and refraction with
// their Fresnel weights. Interface: lessons/11-classics/whitted.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/whitted.h"
#include "todo.h"

namespace ps {

GlassSplit glassSplit(const Material& m, const Vec3& n, const Vec3& wo) {
    // TODO(11) Eq. 11.8: with c = dot(n, wo): wo is outside (eta_o = 1, eta_t = m.ior) if c > 0,
    //          else inside (eta_o = m.ior, eta_t = 1); ns = the normal on wo's side (c > 0 ? n :
    //          -n). reflected = reflect(wo, ns); F = fresnelDielectric(|c|, eta_o, eta_t).
    //          Snell with eta = eta_o / eta_t: sin^2 theta_t = eta^2 (1 - c^2); if it is >= 1 the
    //          ray is totally reflected (F = 1, no refracted branch); else
    //          refracted = normalize(-eta wo + (eta |c| - cos theta_t) ns) and
    //          transmission = (1 - F) eta^2.
    //          Pitfall: inside the glass eta_o is the glass's index: leaving it, eta = ior / 1.
    (void)m; (void)n; (void)wo;
    return PS_TODO("lesson 11: glassSplit", GlassSplit());
}

}  // namespace ps
