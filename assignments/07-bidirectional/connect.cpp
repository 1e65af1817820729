// Lesson 7 — joining a light and a camera subpath: technique (s, t) (Eq. 7.2, 7.4) and the
// reverse pdfs the connection creates (Eq. 7.6). Interface: lessons/07-bidirectional/bpt.h.
// Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

ReversePdfs connectionPdfs(const Scene& scene, const SubpathVertex* y, int s, const SubpathVertex* z, int t) {
    // TODO(07) Eq. 7.6, with zEnd = z[t-1], zPrev = z[t-2] (if t >= 2), yEnd = y[s-1],
    //          yPrev = y[s-2] (if s >= 2); leave a field 0 where its vertex does not exist:
    //          s = 0 (zEnd is the light): cameraEnd = pdfLightOrigin(zEnd),
    //                 cameraPrev = pdfLightToward(zEnd, zPrev).
    //          s >= 1: cameraEnd = s == 1 ? pdfLightToward(yEnd, zEnd) : pdfScatter(yPrev, yEnd, zEnd, Importance);
    //                  cameraPrev = pdfScatter(yEnd, zEnd, zPrev, Importance);
    //                  lightEnd = pdfScatter(zPrev or null, zEnd, yEnd, Radiance);
    //                  lightPrev = pdfScatter(zEnd, yEnd, yPrev, Radiance).
    //          (pdfScatter(scene, prev pointer, cur, next, Transport::...): Importance continues the
    //          light subpath's walk, Radiance the camera subpath's.)
    (void)scene; (void)y; (void)s; (void)z; (void)t;
    return PS_TODO("lesson 07: connectionPdfs", ReversePdfs());
}

Connection connect(const Scene& scene, const Subpath& light, const Subpath& camera, int s, int t, float uLight,
                   const Vec2& uPos) {
    // TODO(07) Technique (s, t) (Eq. 7.2, 7.4); zEnd = camera[t-1], yEnd = light[s-1]:
    //          s = 0 (t >= 2): zEnd at infinity: value = zEnd.beta * scene.backgroundRadiance();
    //            zEnd on an area light (zEnd.light >= 0): value = zEnd.beta *
    //            emittedRadiance(light, zEnd.sp.n, unit direction to camera[t-2]).
    //          t = 1 (s >= 1): sampledLight = light[0] (so that y for the MIS is the same array);
    //            not valid if yEnd is at infinity; cc = connectToCamera(scene, yEnd.sp,
    //            yEnd.onSurface()), not valid if !cc.valid; f = the light's intensity (point),
    //            emittedRadiance(light, n, cc.wCam) (area) when s = 1, else
    //            evalBSDF(m, n, cc.wCam, towards light[s-2]); value = yEnd.beta f cc.importance,
    //            raster = cc.raster.
    //          s = 1 (t >= 2): not valid if zEnd is at infinity or delta; l =
    //            scene.selectLight(uLight, P), ls = sampleLight(scene, l, zEnd.sp.p, uPos);
    //            sampledLight: kind Light, light = l, sp.p = ls.p, sp.n = ls.n (background:
    //            -ls.wi, infinite; point: deltaPosition), pdfFwd = pdfLightOrigin, beta = 1 /
    //            pdfFwd (not valid if 0); G = |cos_z| (cos_l = |dot(ls.n, ls.wi)| / dist^2 for
    //            an area light, 1 / dist^2 for a point light, 1 for the background);
    //            value = zEnd.beta f_z(towards camera[t-2], ls.wi) ls.Le G beta_l; then the
    //            shadow ray (as lesson 2's next-event estimation: spawnRayTo a SurfacePoint on
    //            the light with errScale maxAbsComponent(ls.p), spawnRayTo(ls.p) for a point
    //            light, spawnRay(ls.wi) for the background).
    //          s, t >= 2: not valid if zEnd is at infinity; d = yEnd.p - zEnd.p, w = d / |d|;
    //            value = yEnd.beta f_y(towards z: -w, towards light[s-2]) G f_z(towards
    //            camera[t-2], w) zEnd.beta with G = |cos_y| |cos_z| / |d|^2; f_x(a, b) =
    //            evalBSDF(material, n, a, b) (camera-side direction first); then unless black
    //            the shadow ray scene.spawnRayTo(zEnd.sp, yEnd.sp).
    //          ("towards a vertex" = directionTo(from, to) of bpt.h.)
    //          valid = value is not black (and unoccluded); finally
    //          rev = connectionPdfs(scene, s == 1 ? &sampledLight : light.data(), s, camera.data(), t).
    (void)scene; (void)light; (void)camera; (void)s; (void)t; (void)uLight; (void)uPos;
    return PS_TODO("lesson 07: connect", Connection());
}

}  // namespace ps
