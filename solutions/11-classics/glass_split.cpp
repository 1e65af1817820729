// Lesson 11 — the two branches of glass in Whitted's recursion: reflection and refraction with
// their Fresnel weights. Interface: lessons/11-classics/whitted.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/whitted.h"
#include "todo.h"

namespace ps {

GlassSplit glassSplit(const Material& m, const Vec3& n, const Vec3& wo) {
    //! TODO(11) Both branches of the dielectric for radiance arriving from wo (Eq. 11.8; GlassSplit in whitted.h),
    //!          total internal reflection included. Pitfall (README 6): inside the glass eta_o is the glass's index;
    //!          eta^2 changes too.
    //! STUB (void)m; (void)n; (void)wo;
    //! STUB return PS_TODO("lesson 11: glassSplit", GlassSplit());
    //! BEGIN
    GlassSplit g;
    const float c = glm::dot(n, wo);
    const bool outside = c > 0.0f;
    const float etaO = outside ? 1.0f : m.ior, etaT = outside ? m.ior : 1.0f;
    const Vec3 ns = outside ? n : -n;
    const float cosO = std::abs(c);
    g.reflected = reflect(wo, ns);
    g.reflectance = fresnelDielectric(cosO, etaO, etaT);
    const float eta = etaO / etaT;
    const float sin2T = eta * eta * (1.0f - cosO * cosO);
    if (sin2T >= 1.0f) {
        g.reflectance = 1.0f;
        return g;
    }
    const float cosT = std::sqrt(1.0f - sin2T);
    g.refracted = glm::normalize(-eta * wo + (eta * cosO - cosT) * ns);
    g.transmission = (1.0f - g.reflectance) * eta * eta;
    return g;
    //! END
}

}  // namespace ps
