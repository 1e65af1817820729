// Lesson 7 — joining a light and a camera subpath: technique (s, t) (Eq. 7.2, 7.4) and the
// reverse pdfs the connection creates (Eq. 7.6). Interface: lessons/07-bidirectional/bpt.h.
// Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

ReversePdfs connectionPdfs(const Scene& scene, const SubpathVertex* y, int s, const SubpathVertex* z, int t) {
    //! TODO(07) Eq. 7.6, with zEnd = z[t-1], zPrev = z[t-2] (if t >= 2), yEnd = y[s-1],
    //!          yPrev = y[s-2] (if s >= 2); leave a field 0 where its vertex does not exist:
    //!          s = 0 (zEnd is the light): cameraEnd = pdfLightOrigin(zEnd),
    //!                 cameraPrev = pdfLightToward(zEnd, zPrev).
    //!          s >= 1: cameraEnd = s == 1 ? pdfLightToward(yEnd, zEnd) : pdfScatter(yPrev, yEnd, zEnd, Importance);
    //!                  cameraPrev = pdfScatter(yEnd, zEnd, zPrev, Importance);
    //!                  lightEnd = pdfScatter(zPrev or null, zEnd, yEnd, Radiance);
    //!                  lightPrev = pdfScatter(zEnd, yEnd, yPrev, Radiance).
    //!          (pdfScatter(scene, prev pointer, cur, next, Transport::...): Importance continues the
    //!          light subpath's walk, Radiance the camera subpath's.)
    //! STUB (void)scene; (void)y; (void)s; (void)z; (void)t;
    //! STUB return PS_TODO("lesson 07: connectionPdfs", ReversePdfs());
    //! BEGIN
    ReversePdfs r;
    const SubpathVertex& zEnd = z[t - 1];
    const SubpathVertex* zPrev = t >= 2 ? &z[t - 2] : nullptr;
    if (s == 0) {
        r.cameraEnd = pdfLightOrigin(scene, zEnd);
        if (zPrev) r.cameraPrev = pdfLightToward(scene, zEnd, *zPrev);
        return r;
    }
    const SubpathVertex& yEnd = y[s - 1];
    const SubpathVertex* yPrev = s >= 2 ? &y[s - 2] : nullptr;
    r.cameraEnd = s == 1 ? pdfLightToward(scene, yEnd, zEnd) : pdfScatter(scene, yPrev, yEnd, zEnd, Transport::Importance);
    if (zPrev) r.cameraPrev = pdfScatter(scene, &yEnd, zEnd, *zPrev, Transport::Importance);
    r.lightEnd = pdfScatter(scene, zPrev, zEnd, yEnd, Transport::Radiance);
    if (yPrev) r.lightPrev = pdfScatter(scene, &zEnd, yEnd, *yPrev, Transport::Radiance);
    return r;
    //! END
}

Connection connect(const Scene& scene, const Subpath& light, const Subpath& camera, int s, int t, float uLight,
                   const Vec2& uPos) {
    //! TODO(07) Technique (s, t) (Eq. 7.2, 7.4); zEnd = camera[t-1], yEnd = light[s-1]:
    //!          s = 0 (t >= 2): zEnd at infinity: value = zEnd.beta * scene.backgroundRadiance();
    //!            zEnd on an area light (zEnd.light >= 0): value = zEnd.beta *
    //!            emittedRadiance(light, zEnd.sp.n, unit direction to camera[t-2]).
    //!          t = 1 (s >= 1): sampledLight = light[0] (so that y for the MIS is the same array);
    //!            not valid if yEnd is at infinity; cc = connectToCamera(scene, yEnd.sp,
    //!            yEnd.onSurface()), not valid if !cc.valid; f = the light's intensity (point),
    //!            emittedRadiance(light, n, cc.wCam) (area) when s = 1, else
    //!            evalBSDF(m, n, cc.wCam, towards light[s-2]); value = yEnd.beta f cc.importance,
    //!            raster = cc.raster.
    //!          s = 1 (t >= 2): not valid if zEnd is at infinity or delta; l =
    //!            scene.selectLight(uLight, P), ls = sampleLight(scene, l, zEnd.sp.p, uPos);
    //!            sampledLight: kind Light, light = l, sp.p = ls.p, sp.n = ls.n (background:
    //!            -ls.wi, infinite; point: deltaPosition), pdfFwd = pdfLightOrigin, beta = 1 /
    //!            pdfFwd (not valid if 0); G = |cos_z| (cos_l = |dot(ls.n, ls.wi)| / dist^2 for
    //!            an area light, 1 / dist^2 for a point light, 1 for the background);
    //!            value = zEnd.beta f_z(towards camera[t-2], ls.wi) ls.Le G beta_l; then the
    //!            shadow ray (as lesson 2's next-event estimation: spawnRayTo a SurfacePoint on
    //!            the light with errScale maxAbsComponent(ls.p), spawnRayTo(ls.p) for a point
    //!            light, spawnRay(ls.wi) for the background).
    //!          s, t >= 2: not valid if zEnd is at infinity; d = yEnd.p - zEnd.p, w = d / |d|;
    //!            value = yEnd.beta f_y(towards z: -w, towards light[s-2]) G f_z(towards
    //!            camera[t-2], w) zEnd.beta with G = |cos_y| |cos_z| / |d|^2; f_x(a, b) =
    //!            evalBSDF(material, n, a, b) (camera-side direction first); then unless black
    //!            the shadow ray scene.spawnRayTo(zEnd.sp, yEnd.sp).
    //!          ("towards a vertex" = directionTo(from, to) of bpt.h.)
    //!          valid = value is not black (and unoccluded); finally
    //!          rev = connectionPdfs(scene, s == 1 ? &sampledLight : light.data(), s, camera.data(), t).
    //! STUB (void)scene; (void)light; (void)camera; (void)s; (void)t; (void)uLight; (void)uPos;
    //! STUB return PS_TODO("lesson 07: connect", Connection());
    //! BEGIN
    Connection c;
    const SubpathVertex& zEnd = camera[size_t(t - 1)];
    const auto towards = directionTo;
    const auto material = [&](const SubpathVertex& v) -> const Material& { return scene.materials[size_t(v.sp.material)]; };
    if (s == 0) {
        if (zEnd.infinite) c.value = zEnd.beta * scene.backgroundRadiance();
        else if (zEnd.light >= 0 && zEnd.kind == VertexKind::Surface)
            c.value = zEnd.beta * emittedRadiance(scene.lights[size_t(zEnd.light)], zEnd.sp.n,
                                                  towards(zEnd, camera[size_t(t - 2)]));
        c.valid = !isBlack(c.value);
    } else if (t == 1) {
        c.sampledLight = light[0];
        const SubpathVertex& yEnd = light[size_t(s - 1)];
        if (yEnd.infinite) return c;
        const CameraConnection cc = connectToCamera(scene, yEnd.sp, yEnd.onSurface());
        if (!cc.valid) return c;
        Color f;
        if (s == 1) {
            const Light& l = scene.lights[size_t(yEnd.light)];
            f = l.isDelta() ? l.Le : emittedRadiance(l, yEnd.sp.n, cc.wCam);
        } else {
            f = evalBSDF(material(yEnd), yEnd.sp.n, cc.wCam, towards(yEnd, light[size_t(s - 2)]));
        }
        c.value = yEnd.beta * f * cc.importance;
        c.raster = cc.raster;
        c.valid = !isBlack(c.value);
    } else if (s == 1) {
        if (zEnd.infinite) return c;
        float P = 0.0f;
        const int l = scene.selectLight(uLight, P);
        if (l < 0) return c;
        const LightSample ls = sampleLight(scene, l, zEnd.sp.p, uPos);
        const Light& lt = scene.lights[size_t(l)];
        SubpathVertex& y0 = c.sampledLight;
        y0.kind = VertexKind::Light;
        y0.light = l;
        y0.sp.p = ls.p;
        y0.sp.n = ls.n;
        y0.sp.errScale = maxAbsComponent(ls.p);
        y0.deltaPosition = lt.isDelta();
        y0.infinite = lt.isInfinite();
        if (y0.infinite || y0.deltaPosition) y0.sp.n = -ls.wi;
        y0.pdfFwd = pdfLightOrigin(scene, y0);
        if (!(y0.pdfFwd > 0.0f && ls.pdf > 0.0f)) return c;
        y0.beta = Color(1.0f / y0.pdfFwd);
        float G = std::abs(glm::dot(zEnd.sp.n, ls.wi));
        if (lt.kind == LightKind::Area) G *= std::abs(glm::dot(ls.n, ls.wi)) / (ls.dist * ls.dist);
        else if (lt.kind == LightKind::Point) G /= ls.dist * ls.dist;
        const Color fz = evalBSDF(material(zEnd), zEnd.sp.n, towards(zEnd, camera[size_t(t - 2)]), ls.wi);
        c.value = zEnd.beta * fz * ls.Le * G * y0.beta;
        if (isBlack(c.value) || !isFinite(c.value)) {
            c.value = isFinite(c.value) ? c.value : Color(0.0f);
            return c;
        }
        bool visible = false;
        switch (lt.kind) {
        case LightKind::Area: visible = !scene.occluded(scene.spawnRayTo(zEnd.sp, y0.sp)); break;
        case LightKind::Point: visible = !scene.occluded(scene.spawnRayTo(zEnd.sp, ls.p)); break;
        case LightKind::Background: visible = !scene.occluded(scene.spawnRay(zEnd.sp, ls.wi)); break;
        }
        c.valid = visible;
    } else {
        const SubpathVertex& yEnd = light[size_t(s - 1)];
        if (zEnd.infinite) return c;
        const Vec3 d = yEnd.sp.p - zEnd.sp.p;
        const float d2 = glm::dot(d, d);
        if (!(d2 > 0.0f)) return c;
        const Vec3 w = d / std::sqrt(d2);
        const Color fy = evalBSDF(material(yEnd), yEnd.sp.n, -w, towards(yEnd, light[size_t(s - 2)]));
        const Color fz = evalBSDF(material(zEnd), zEnd.sp.n, towards(zEnd, camera[size_t(t - 2)]), w);
        const float G = std::abs(glm::dot(yEnd.sp.n, w)) * std::abs(glm::dot(zEnd.sp.n, w)) / d2;
        c.value = yEnd.beta * fy * G * fz * zEnd.beta;
        if (isBlack(c.value)) return c;
        c.valid = !scene.occluded(scene.spawnRayTo(zEnd.sp, yEnd.sp));
    }
    if (!c.valid) return c;
    c.rev = connectionPdfs(scene, s == 1 ? &c.sampledLight : light.data(), s, camera.data(), t);
    return c;
    //! END
}

}  // namespace ps
