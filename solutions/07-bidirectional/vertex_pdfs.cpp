// Lesson 7 — the densities of path vertices (Eq. 7.3): one set of functions for sampling the
// subpaths and for the MIS weights, so that the 1/d^2 of a short connection cancels exactly.
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

float convertToArea(float pdfW, const SubpathVertex& from, const SubpathVertex& to) {
    //! TODO(07) Eq. 7.3: if `to` is at infinity return pdfW unchanged; else w = to.sp.p - from.sp.p,
    //!          d2 = |w|^2, 0 if d2 is 0; pdf = pdfW / d2, times |cos| = |dot(to.sp.n, w)| / sqrt(d2)
    //!          if to.onSurface().
    //! STUB (void)pdfW; (void)from; (void)to;
    //! STUB return PS_TODO("lesson 07: convertToArea", 0.0f);
    //! BEGIN
    if (to.infinite) return pdfW;
    const Vec3 w = to.sp.p - from.sp.p;
    const float d2 = glm::dot(w, w);
    if (!(d2 > 0.0f)) return 0.0f;
    float pdf = pdfW / d2;
    if (to.onSurface()) pdf *= std::abs(glm::dot(to.sp.n, w)) / std::sqrt(d2);
    return pdf;
    //! END
}

float pdfLightOrigin(const Scene& scene, const SubpathVertex& v) {
    //! TODO(07) Eq. 7.3: P = scene.lightSelectionProb(v.light) (0 if v.light < 0); background:
    //!          P * pdfBackgroundDirection(); point light: P; area light: P * pdfLightArea(scene, l).
    //! STUB (void)scene; (void)v;
    //! STUB return PS_TODO("lesson 07: pdfLightOrigin", 0.0f);
    //! BEGIN
    if (v.light < 0) return 0.0f;
    const float P = scene.lightSelectionProb(v.light);
    const Light& light = scene.lights[size_t(v.light)];
    if (light.isInfinite()) return P * pdfBackgroundDirection();
    if (light.isDelta()) return P;
    return P * pdfLightArea(scene, v.light);
    //! END
}

float pdfLightToward(const Scene& scene, const SubpathVertex& light, const SubpathVertex& to) {
    //! TODO(07) Eq. 7.3, the densities sampleEmission uses: background: 1 / (pi R^2) with
    //!          R = scene.radius, times |dot(to.sp.n, light.sp.n)| if to.onSurface() (parallel
    //!          rays from a disk); point light: convertToArea(1 / (4 pi)); area light: the
    //!          cosine density max(0, dot(light.sp.n, w)) / pi of the unit direction w from the
    //!          light to `to`, through convertToArea.
    //! STUB (void)scene; (void)light; (void)to;
    //! STUB return PS_TODO("lesson 07: pdfLightToward", 0.0f);
    //! BEGIN
    if (light.infinite) {
        float pdf = 1.0f / (kPi * scene.radius * scene.radius);
        if (to.onSurface()) pdf *= std::abs(glm::dot(to.sp.n, light.sp.n));
        return pdf;
    }
    if (light.deltaPosition) return convertToArea(uniformSpherePdf(), light, to);
    const Vec3 w = to.sp.p - light.sp.p;
    const float len = glm::length(w);
    if (!(len > 0.0f)) return 0.0f;
    const float cosL = glm::dot(light.sp.n, w / len);
    return cosL > 0.0f ? convertToArea(cosL * kInvPi, light, to) : 0.0f;
    //! END
}

float pdfScatter(const Scene& scene, const SubpathVertex* prev, const SubpathVertex& cur, const SubpathVertex& next,
                 Transport mode) {
    //! TODO(07) Eq. 7.3, 7.7a: the unit direction wn = directionTo(cur, next) (bpt.h); camera:
    //!          pdfW = scene.camera.pdfDirection(wn); surface (prev not null), wp =
    //!          directionTo(cur, *prev), m its material: not delta: pdfW = pdfBSDF(m, cur.sp.n, wp, wn);
    //!          delta: the coefficient of its Dirac delta from lesson 6's deltaLobe (paths.h), NOT 0:
    //!          mode Importance (light flows from prev to next): deltaLobe(m, n, wp, wn).pdfLight;
    //!          mode Radiance (light flows from next to prev): deltaLobe(m, n, wn, wp).pdfCamera;
    //!          (use its numbers even if lobe.valid is false: the walk itself chose this direction,
    //!          and on a very short segment rounding of the positions can exceed deltaLobe's
    //!          tolerance; they are 0 only if no lobe connects the two sides). Return
    //!          convertToArea(pdfW, cur, next).
    //! STUB (void)scene; (void)prev; (void)cur; (void)next; (void)mode;
    //! STUB return PS_TODO("lesson 07: pdfScatter", 0.0f);
    //! BEGIN
    const Vec3 wn = directionTo(cur, next);
    float pdfW = 0.0f;
    if (cur.kind == VertexKind::Camera) {
        pdfW = scene.camera.pdfDirection(wn);
    } else {
        if (prev == nullptr) return 0.0f;
        const Material& m = scene.materials[size_t(cur.sp.material)];
        const Vec3 wp = directionTo(cur, *prev);
        if (cur.delta) {
            const DeltaLobe lobe = mode == Transport::Importance ? deltaLobe(m, cur.sp.n, wp, wn) : deltaLobe(m, cur.sp.n, wn, wp);
            pdfW = mode == Transport::Importance ? lobe.pdfLight : lobe.pdfCamera;
        } else {
            pdfW = pdfBSDF(m, cur.sp.n, wp, wn);
        }
    }
    return convertToArea(pdfW, cur, next);
    //! END
}

}  // namespace ps
