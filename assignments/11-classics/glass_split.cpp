// Lesson 11 — the two branches of glass in Whitted's recursion: reflection and refraction with
// their Fresnel weights. Interface: lessons/11-classics/whitted.h. Equation numbers refer to
// lessons/11-classics/README.md.
#include "11-classics/whitted.h"
#include "todo.h"

namespace ps {

GlassSplit glassSplit(const Material& m, const Vec3& n, const Vec3& wo) {
    // TODO(11) Both branches of the dielectric for radiance arriving from wo (Eq. 11.8; GlassSplit in whitted.h),
    //          total internal reflection included. Pitfall (README 6): inside the glass eta_o is the glass's index;
    //          eta^2 changes too.
    (void)m; (void)n; (void)wo;
    return PS_TODO("lesson 11: glassSplit", GlassSplit());
}

}  // namespace ps
