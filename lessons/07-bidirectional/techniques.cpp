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

// Where f is not 0, cur is a non-specular surface (a delta BSDF's f is 0), so both densities are
// pdfScatter's BSDF case: pdfBSDF in the walk's order, converted to area (Eq. 7.3). They are
// evaluated here from the two directions f already needed, the same calls with the same numbers
// as pdfScatter's (so the same bits), without normalising the directions again: a connection
// took 4 % of a `bpt` iteration's instructions in pdfScatter's own work (bench/README.md, issue
// 30). Your pdfScatter still gives every subpath vertex's pdfFwd and pdfRev and the densities
// of connectionPdfs.
Scattering scatteringAt(const Scene& scene, const PathVertex& lightSide, const PathVertex& cur,
                        const PathVertex& cameraSide) {
    Scattering e;
    const Material& m = scene.materials[size_t(cur.sp.material)];
    const Vec3 wCamera = direction(cur, cameraSide), wLight = direction(cur, lightSide);
    e.f = evalBSDF(m, cur.sp.n, wCamera, wLight);
    if (isBlack(e.f)) return e;  // no contribution, nothing to weigh (a Phong lobe's back, a delta BSDF)
    e.pdfTowardsCamera = pdfSolidAngleToArea(pdfBSDF(m, cur.sp.n, wLight, wCamera), cur, cameraSide);
    e.pdfTowardsLight = pdfSolidAngleToArea(pdfBSDF(m, cur.sp.n, wCamera, wLight), cur, lightSide);
    return e;
}

}  // namespace ps
