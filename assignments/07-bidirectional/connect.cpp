// Lesson 7 — joining a light and a camera subpath: the four kinds of connection of technique
// (s, t) (Eq. 7.2, 7.4) and the reverse pdfs a connection creates (Eq. 7.6). Interface:
// lessons/07-bidirectional/bpt.h; connect() (lessons/07-bidirectional/techniques.cpp) picks the
// kind and adds the reverse pdfs. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

ReversePdfs connectionPdfs(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t) {
    // TODO(07) The connection's four new reverse densities (Eq. 7.6; ReversePdfs in bpt.h), per unit area. Pitfalls: s
    //          = 1's edge starts at the light, not with a BSDF; a field stays 0 where its vertex does not exist.
    (void)scene; (void)y; (void)s; (void)z; (void)t;
    return PS_TODO("lesson 07: connectionPdfs", ReversePdfs());
}

Connection connectEmitter(const Scene& scene, const PathVertex* z, int t) {
    // TODO(07) C*_{0,t} (Eq. 7.2, 7.4; connectEmitter in bpt.h). Pitfall: the emission leaves z_{t-1} towards z_{t-2}
    //          (the back of an area light is black).
    (void)scene; (void)z; (void)t;
    return PS_TODO("lesson 07: connectEmitter", Connection());
}

Connection connectCamera(const Scene& scene, const PathVertex* y, int s, const PathVertex& z0) {
    // TODO(07) C*_{s,1} and where it lands (Eq. 7.2, 7.4; connectCamera in bpt.h), through lesson 5's camera
    //          connection. Pitfalls: no cosine at a point light; a background y_0 cannot be joined to the camera (Eq.
    //          7.12).
    (void)scene; (void)y; (void)s; (void)z0;
    return PS_TODO("lesson 07: connectCamera", Connection());
}

Connection connectLight(const Scene& scene, const PathVertex* z, int t, float uLight, const Vec2& uPos) {
    // TODO(07) C*_{1,t} with its own new light vertex (Eq. 7.2, 7.4; connectLight in bpt.h), not valid where the light
    //          sample has no density. Pitfalls (README 6): that vertex's density is the light subpath's (Eq. 7.3, with
    //          P(l)), not the light sample's; the shadow ray to a point light or the background is not one to a
    //          surface point.
    (void)scene; (void)z; (void)t; (void)uLight; (void)uPos;
    return PS_TODO("lesson 07: connectLight", Connection());
}

Connection connectVertices(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t) {
    // TODO(07) C*_{s,t} and its reverse densities (Eq. 7.2, 7.4, 7.6; connectVertices in bpt.h), each endpoint's f and
    //          densities from one scattering event. Pitfalls: each endpoint's light and camera side; a background end
    //          cannot be joined; two coincident points give nothing, not NaN.
    (void)scene; (void)y; (void)s; (void)z; (void)t;
    return PS_TODO("lesson 07: connectVertices", Connection());
}

}  // namespace ps
