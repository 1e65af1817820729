// Lesson 7 — the densities of path vertices (Eq. 7.3): one set of functions for sampling the
// subpaths and for the MIS weights, so that the 1/d^2 of a short connection cancels exactly.
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

float pdfLightOrigin(const Scene& scene, const PathVertex& v) {
    //! TODO(07) The density of the light vertex v itself (Eq. 7.3; pdfLightOrigin in bpt.h). Pitfall: P(l); 0 on no
    //!          light.
    //! STUB (void)scene; (void)v;
    //! STUB return PS_TODO("lesson 07: pdfLightOrigin", 0.0f);
    //! BEGIN
    if (v.sp.light < 0) return 0.0f;
    const EmissionPdf e = pdfEmission(scene, v.sp.light, v.sp.n, v.sp.n);  // pdfA does not depend on the direction
    return scene.lightSelectionProb(v.sp.light) * (v.infinite ? e.pdfW : e.pdfA);
    //! END
}

float pdfLightToward(const Scene& scene, const PathVertex& light, const PathVertex& to) {
    //! TODO(07) The area density of the emitted direction at `to` (Eq. 7.3; pdfLightToward in bpt.h), the background's
    //!          from its disk. Pitfall: 0 on no light.
    //! STUB (void)scene; (void)light; (void)to;
    //! STUB return PS_TODO("lesson 07: pdfLightToward", 0.0f);
    //! BEGIN
    if (light.sp.light < 0) return 0.0f;
    const EmissionPdf e = pdfEmission(scene, light.sp.light, light.sp.n, direction(light, to));
    if (light.infinite) return to.onSurface() ? e.pdfA * std::abs(glm::dot(to.sp.n, light.sp.n)) : e.pdfA;
    return pdfSolidAngleToArea(e.pdfW, light, to);
    //! END
}

float pdfScatter(const Scene& scene, const PathVertex* prev, const PathVertex& cur, const PathVertex& next,
                 Transport mode) {
    //! TODO(07) The area density with which cur samples next (Eq. 7.3, 7.7a; pdfScatter in bpt.h), walking in `mode`.
    //!          Pitfalls (README 6): a specular cur's density is its delta's coefficient, not 0, even when the lobe is
    //!          not valid; the BSDF's arguments in the walk's order.
    //! STUB (void)scene; (void)prev; (void)cur; (void)next; (void)mode;
    //! STUB return PS_TODO("lesson 07: pdfScatter", 0.0f);
    //! BEGIN
    const Vec3 wn = direction(cur, next);
    float pdfW = 0.0f;
    if (cur.isCamera()) {
        pdfW = scene.camera.pdfDirection(cur.p(), wn);
    } else {
        if (prev == nullptr) return 0.0f;
        const Material& m = scene.materials[size_t(cur.sp.material)];
        const Vec3 wp = direction(cur, *prev);
        if (cur.specular) {
            const DeltaLobe lobe =
                mode == Transport::Importance ? deltaLobe(m, cur.sp.n, wp, wn) : deltaLobe(m, cur.sp.n, wn, wp);
            pdfW = mode == Transport::Importance ? lobe.pdfLight : lobe.pdfCamera;
        } else {
            pdfW = pdfBSDF(m, cur.sp.n, wp, wn);
        }
    }
    return pdfSolidAngleToArea(pdfW, cur, next);
    //! END
}

}  // namespace ps
