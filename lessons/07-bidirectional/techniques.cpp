// Lesson 7 — technique (s, t) (plumbing: read it, nothing to write here): picks the kind of
// connection of Eq. 7.4 (connect.cpp, yours) and adds the reverse pdfs the connection creates
// (Eq. 7.6); a scattering event's f and both densities in one call (scatteringAt), which
// connectVertices uses for its value and its reverse pdfs. Interface: lessons/07-bidirectional/bpt.h.
#include "07-bidirectional/bpt.h"

namespace ps {

Connection connectCamera(const Scene& scene, const PathVertex* y, int s) {
    return connectCamera(scene, y, s, cameraVertex(scene));
}

Connection connect(const Scene& scene, const Subpath& light, const Subpath& camera, int s, int t, float uLight,
                   const Vec2& uPos) {
    Connection c;
    if (s == 0) c = connectEmitter(scene, camera.data(), t);
    else if (t == 1) {
        c = connectCamera(scene, light.data(), s, camera[0]);  // the camera subpath's z_0
        c.sampledLight = light[0];                             // the MIS reads y_0 from here whenever s = 1
    } else if (s == 1) c = connectLight(scene, camera.data(), t, uLight, uPos);
    else c = connectVertices(scene, light.data(), s, camera.data(), t);  // rev too (scatteringAt)
    if (c.valid && (s < 2 || t < 2))
        c.rev = connectionPdfs(scene, s == 1 ? &c.sampledLight : light.data(), s, camera.data(), t);
    return c;
}

Scattering scatteringAt(const Scene& scene, const PathVertex& lightSide, const PathVertex& cur,
                        const PathVertex& cameraSide) {
    Scattering e;
    e.f = evalBSDF(scene.materials[size_t(cur.sp.material)], cur.sp.n, direction(cur, cameraSide),
                   direction(cur, lightSide));
    if (isBlack(e.f)) return e;  // no contribution, nothing to weigh (a Phong lobe's back, a delta BSDF)
    e.pdfTowardsCamera = pdfScatter(scene, &lightSide, cur, cameraSide, Transport::Importance);
    e.pdfTowardsLight = pdfScatter(scene, &cameraSide, cur, lightSide, Transport::Radiance);
    return e;
}

}  // namespace ps
