// Lesson 7 — joining a light and a camera subpath: technique (s, t) (Eq. 7.2, 7.4) and the
// reverse pdfs the connection creates (Eq. 7.6). Interface: lessons/07-bidirectional/bpt.h.
// Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

ReversePdfs connectionPdfs(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t) {
    //! TODO(07) Eq. 7.6: the four densities the connection y_{s-1} -- z_{t-1} creates, with
    //!          pdfLightOrigin / pdfLightToward when z_{t-1} is itself the light (s = 0), else
    //!          pdfScatter continuing each walk across the edge (Importance towards the camera,
    //!          Radiance towards the light). Pitfall: s = 1 starts with pdfLightToward, not
    //!          pdfScatter; leave a field 0 where its vertex does not exist.
    //! STUB (void)scene; (void)y; (void)s; (void)z; (void)t;
    //! STUB return PS_TODO("lesson 07: connectionPdfs", ReversePdfs());
    //! BEGIN
    ReversePdfs r;
    const PathVertex& zEnd = z[t - 1];
    const PathVertex* zPrev = t >= 2 ? &z[t - 2] : nullptr;
    if (s == 0) {
        r.cameraEnd = pdfLightOrigin(scene, zEnd);
        if (zPrev) r.cameraPrev = pdfLightToward(scene, zEnd, *zPrev);
        return r;
    }
    const PathVertex& yEnd = y[s - 1];
    const PathVertex* yPrev = s >= 2 ? &y[s - 2] : nullptr;
    r.cameraEnd = s == 1 ? pdfLightToward(scene, yEnd, zEnd) : pdfScatter(scene, yPrev, yEnd, zEnd, Transport::Importance);
    if (zPrev) r.cameraPrev = pdfScatter(scene, &yEnd, zEnd, *zPrev, Transport::Importance);
    r.lightEnd = pdfScatter(scene, zPrev, zEnd, yEnd, Transport::Radiance);
    if (yPrev) r.lightPrev = pdfScatter(scene, &zEnd, yEnd, *yPrev, Transport::Radiance);
    return r;
    //! END
}

Connection connect(const Scene& scene, const Subpath& light, const Subpath& camera, int s, int t, float uLight,
                   const Vec2& uPos) {
    //! TODO(07) Eq. 7.2, 7.4: the unweighted contribution C*_{s,t} = beta_y f_y G f_z beta_z with
    //!          lesson 6's geometryTerm, for s = 0 (z_{t-1} emits), t = 1 (connectToCamera), s = 1
    //!          (a fresh sampleLight into c.sampledLight, pdfFwd = pdfLightOrigin, beta = 1 / pdfFwd)
    //!          and s, t >= 2, each after its shadow ray (s = 1: as lesson 2's next-event
    //!          estimation); valid = not black and unoccluded; then rev = connectionPdfs.
    //!          Pitfalls: f_x = evalBSDF(m, n, camera-side direction, light-side direction); s >= 1
    //!          never joins at a specular or background endpoint; t = 1 sets c.sampledLight =
    //!          light[0] too (the MIS reads y from it whenever s = 1); the background y_0's sp.n
    //!          points towards the background (ls.wi).
    //! STUB (void)scene; (void)light; (void)camera; (void)s; (void)t; (void)uLight; (void)uPos;
    //! STUB return PS_TODO("lesson 07: connect", Connection());
    //! BEGIN
    Connection c;
    const PathVertex& zEnd = camera[size_t(t - 1)];
    const auto material = [&](const PathVertex& v) -> const Material& { return scene.materials[size_t(v.sp.material)]; };
    if (s == 0) {
        if (zEnd.infinite) c.value = zEnd.beta * scene.backgroundRadiance();
        else if (zEnd.onLight)
            c.value = zEnd.beta * emittedRadiance(scene.lights[size_t(zEnd.sp.light)], zEnd.sp.n,
                                                  direction(zEnd, camera[size_t(t - 2)]));
        c.valid = !isBlack(c.value);
    } else if (t == 1) {
        c.sampledLight = light[0];
        const PathVertex& yEnd = light[size_t(s - 1)];
        if (yEnd.infinite) return c;
        const CameraConnection cc = connectToCamera(scene, yEnd.sp, yEnd.onSurface());
        if (!cc.valid) return c;
        Color f;
        if (s == 1) {
            const Light& l = scene.lights[size_t(yEnd.sp.light)];
            f = l.isDelta() ? l.Le : emittedRadiance(l, yEnd.sp.n, cc.wCam);
        } else {
            f = evalBSDF(material(yEnd), yEnd.sp.n, cc.wCam, direction(yEnd, light[size_t(s - 2)]));
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
        PathVertex& y0 = c.sampledLight;
        y0.sp.p = ls.p;
        y0.sp.n = ls.n;
        y0.sp.errScale = maxAbsComponent(ls.p);
        y0.sp.light = l;
        y0.onLight = true;
        y0.pointLight = lt.isDelta();
        y0.infinite = lt.isInfinite();
        if (y0.infinite) y0.sp.n = ls.wi;   // towards the background (lesson 6's convention)
        y0.pdfFwd = pdfLightOrigin(scene, y0);
        if (!(y0.pdfFwd > 0.0f && ls.pdf > 0.0f)) return c;
        y0.beta = Color(1.0f / y0.pdfFwd);
        const float G = geometryTerm(y0, zEnd);
        const Color fz = evalBSDF(material(zEnd), zEnd.sp.n, direction(zEnd, camera[size_t(t - 2)]), ls.wi);
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
        const PathVertex& yEnd = light[size_t(s - 1)];
        if (zEnd.infinite) return c;
        const Vec3 w = direction(zEnd, yEnd);
        if (w == Vec3(0.0f)) return c;
        const Color fy = evalBSDF(material(yEnd), yEnd.sp.n, -w, direction(yEnd, light[size_t(s - 2)]));
        const Color fz = evalBSDF(material(zEnd), zEnd.sp.n, direction(zEnd, camera[size_t(t - 2)]), w);
        const float G = geometryTerm(yEnd, zEnd);
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
