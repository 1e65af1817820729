// Lesson 5 — the adjoint BSDF: how a particle scatters. Interface:
// lessons/05-light-tracing/lighttracer.h. Equation numbers refer to lessons/05-light-tracing/README.md.
#include "05-light-tracing/lighttracer.h"
#include "todo.h"

namespace ps {

bool sampleAdjointBSDF(const Material& m, const Vec3& n, const Vec3& wLight, const Vec2& u, float uLobe,
                       BSDFSample& s) {
    // TODO(05) The particle's next direction and power factor (Eq. 5.6-5.8), as lighttracer.h specifies; the smooth
    //          dielectric by hand (README 2), reflecting when uLobe < F as framework/bsdf.cpp does. Pitfalls, README
    //          6: the cosine of the arrival direction instead of the sampled one; an eta^2 on refraction.
    (void)m; (void)n; (void)wLight; (void)u; (void)uLobe; (void)s;
    return PS_TODO("lesson 05: sampleAdjointBSDF", false);
}

}  // namespace ps
