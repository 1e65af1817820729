// Lesson 7 — joining a light and a camera subpath: the four kinds of connection of technique
// (s, t) (Eq. 7.2, 7.4) and the reverse pdfs a connection creates (Eq. 7.6). Interface:
// lessons/07-bidirectional/bpt.h; connect() (lessons/07-bidirectional/techniques.cpp) picks the
// kind and adds the reverse pdfs. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

ReversePdfs connectionPdfs(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t) {
    //! TODO(07) The connection's four new reverse densities (Eq. 7.6; ReversePdfs in bpt.h), per unit area. Pitfalls: s
    //!          = 1's edge starts at the light, not with a BSDF; a field stays 0 where its vertex does not exist.
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
    r.cameraEnd =
        s == 1 ? pdfLightToward(scene, yEnd, zEnd) : pdfScatter(scene, yPrev, yEnd, zEnd, Transport::Importance);
    if (zPrev) r.cameraPrev = pdfScatter(scene, &yEnd, zEnd, *zPrev, Transport::Importance);
    r.lightEnd = pdfScatter(scene, zPrev, zEnd, yEnd, Transport::Radiance);
    if (yPrev) r.lightPrev = pdfScatter(scene, &zEnd, yEnd, *yPrev, Transport::Radiance);
    return r;
    //! END
}

Connection connectEmitter(const Scene& scene, const PathVertex* z, int t) {
    //! TODO(07) C*_{0,t} (Eq. 7.2, 7.4; connectEmitter in bpt.h). Pitfall: the emission leaves z_{t-1} towards z_{t-2}
    //!          (the back of an area light is black).
    //! STUB (void)scene; (void)z; (void)t;
    //! STUB return PS_TODO("lesson 07: connectEmitter", Connection());
    //! BEGIN
    Connection c;
    const PathVertex& zEnd = z[t - 1];
    if (zEnd.infinite) {
        c.value = zEnd.beta * scene.backgroundRadiance();
    } else if (zEnd.onLight) {
        const Light& light = scene.lights[size_t(zEnd.sp.light)];
        c.value = zEnd.beta * emittedRadiance(light, zEnd.sp.n, direction(zEnd, z[t - 2]));
    }
    c.valid = !isBlack(c.value);
    return c;
    //! END
}

Connection connectCamera(const Scene& scene, const PathVertex* y, int s, const PathVertex& z0) {
    //! TODO(07) C*_{s,1} and where it lands (Eq. 7.2, 7.4; connectCamera in bpt.h), through lesson 5's camera
    //!          connection. Pitfalls: no cosine at a point light; a background y_0 cannot be joined to the camera (Eq.
    //!          7.12).
    //! STUB (void)scene; (void)y; (void)s; (void)z0;
    //! STUB return PS_TODO("lesson 07: connectCamera", Connection());
    //! BEGIN
    Connection c;
    const PathVertex& yEnd = y[s - 1];
    if (yEnd.infinite) return c;
    const CameraConnection cc = connectToCamera(scene, yEnd.sp, yEnd.onSurface(), z0.p());
    if (!cc.valid) return c;
    Color f;
    if (s == 1) {
        const Light& l = scene.lights[size_t(yEnd.sp.light)];
        f = l.isDelta() ? l.Le : emittedRadiance(l, yEnd.sp.n, cc.wCam);
    } else {
        f = evalBSDF(scene.materials[size_t(yEnd.sp.material)], yEnd.sp.n, cc.wCam, direction(yEnd, y[s - 2]));
    }
    c.value = yEnd.beta * f * cc.importance;
    c.raster = cc.raster;
    c.valid = !isBlack(c.value);
    return c;
    //! END
}

Connection connectLight(const Scene& scene, const PathVertex* z, int t, float uLight, const Vec2& uPos) {
    //! TODO(07) C*_{1,t} with its own new light vertex (Eq. 7.2, 7.4; connectLight in bpt.h), not valid where the light
    //!          sample has no density. Pitfalls (README 6): that vertex's density is the light subpath's (Eq. 7.3, with
    //!          P(l)), not the light sample's; the shadow ray to a point light or the background is not one to a
    //!          surface point.
    //! STUB (void)scene; (void)z; (void)t; (void)uLight; (void)uPos;
    //! STUB return PS_TODO("lesson 07: connectLight", Connection());
    //! BEGIN
    Connection c;
    const PathVertex& zEnd = z[t - 1];
    if (zEnd.infinite) return c;
    float P = 0.0f;
    const int l = scene.selectLight(uLight, P);
    if (l < 0) return c;
    const LightSample ls = sampleLight(scene, l, zEnd.sp.p, uPos);
    const Light& light = scene.lights[size_t(l)];
    PathVertex& y0 = c.sampledLight;
    y0 = lightVertex(scene, l, ls);  // the background's points towards it (lesson 6's convention)
    y0.pdfFwd = pdfLightOrigin(scene, y0);
    if (!(y0.pdfFwd > 0.0f && (ls.pdfA > 0.0f || ls.pdfW > 0.0f))) return c;
    y0.beta = Color(1.0f / y0.pdfFwd);
    const Color fz = evalBSDF(scene.materials[size_t(zEnd.sp.material)], zEnd.sp.n, direction(zEnd, z[t - 2]), ls.wi);
    c.value = zEnd.beta * fz * ls.Le * geometryTerm(y0, zEnd) * y0.beta;
    if (isBlack(c.value) || !isFinite(c.value)) {
        c.value = isFinite(c.value) ? c.value : Color(0.0f);
        return c;
    }
    switch (light.kind) {
    case LightKind::Area: c.valid = !scene.occluded(scene.spawnRayTo(zEnd.sp, y0.sp)); break;
    case LightKind::Point: c.valid = !scene.occluded(scene.spawnRayTo(zEnd.sp, ls.p)); break;
    case LightKind::Background: c.valid = !scene.occluded(scene.spawnRay(zEnd.sp, ls.wi)); break;
    }
    return c;
    //! END
}

Connection connectVertices(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t) {
    //! TODO(07) C*_{s,t} and its reverse densities (Eq. 7.2, 7.4, 7.6; connectVertices in bpt.h), each endpoint's f and
    //!          densities from one scattering event. Pitfalls: each endpoint's light and camera side; a background end
    //!          cannot be joined; two coincident points give nothing, not NaN.
    //! STUB (void)scene; (void)y; (void)s; (void)z; (void)t;
    //! STUB return PS_TODO("lesson 07: connectVertices", Connection());
    //! BEGIN
    Connection c;
    const PathVertex& yEnd = y[s - 1];
    const PathVertex& zEnd = z[t - 1];
    if (zEnd.infinite || yEnd.infinite) return c;
    if (direction(zEnd, yEnd) == Vec3(0.0f)) return c;
    const Scattering atY = scatteringAt(scene, y[s - 2], yEnd, zEnd);
    if (isBlack(atY.f)) return c;
    const Scattering atZ = scatteringAt(scene, yEnd, zEnd, z[t - 2]);
    c.value = yEnd.beta * atY.f * geometryTerm(yEnd, zEnd) * atZ.f * zEnd.beta;
    if (isBlack(c.value)) return c;
    c.valid = !scene.occluded(scene.spawnRayTo(zEnd.sp, yEnd.sp));
    c.rev.lightEnd = atZ.pdfTowardsLight;
    c.rev.lightPrev = atY.pdfTowardsLight;
    c.rev.cameraEnd = atY.pdfTowardsCamera;
    c.rev.cameraPrev = atZ.pdfTowardsCamera;
    return c;
    //! END
}

}  // namespace ps
