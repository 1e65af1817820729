// Lesson 7 — joining a light and a camera subpath: the four kinds of connection of technique
// (s, t) (Eq. 7.2, 7.4) and the reverse pdfs a connection creates (Eq. 7.6). Interface:
// lessons/07-bidirectional/bpt.h; connect() (lessons/07-bidirectional/techniques.cpp) picks the
// kind and adds the reverse pdfs. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

ReversePdfs connectionPdfs(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t) {
    // TODO(07) Eq. 7.6: the four densities the connection y_{s-1} -- z_{t-1} creates, with
    //          pdfLightOrigin / pdfLightToward when z_{t-1} is itself the light (s = 0), else
    //          pdfScatter continuing each walk across the edge (Importance towards the camera,
    //          Radiance towards the light). Pitfall: s = 1 starts with pdfLightToward, not
    //          pdfScatter; leave a field 0 where its vertex does not exist.
    (void)scene; (void)y; (void)s; (void)z; (void)t;
    return PS_TODO("lesson 07: connectionPdfs", ReversePdfs());
}

Connection connectEmitter(const Scene& scene, const PathVertex* z, int t) {
    // TODO(07) Eq. 7.2, 7.4 (s = 0): the camera subpath ends on a light: C* = beta_{t-1} times
    //          the radiance z_{t-1} sends back along the walk (emittedRadiance of its light, or
    //          the background's). Not valid if z_{t-1} emits nothing.
    //          Pitfall: the emitted direction is from z_{t-1} TOWARDS z_{t-2} (the back of an area
    //          light is black).
    (void)scene; (void)z; (void)t;
    return PS_TODO("lesson 07: connectEmitter", Connection());
}

Connection connectCamera(const Scene& scene, const PathVertex* y, int s, const PathVertex& z0) {
    // TODO(07) Eq. 7.2, 7.4 (t = 1): y_{s-1} joined to the pinhole z0 (its position z0.p(); a
    //          camera model's point) with lesson 5's connectToCamera(..., z0.p()):
    //          C* = beta_{s-1} f importance, f = the BSDF from the camera's
    //          direction to y_{s-2}'s, or for s = 1 what the light sends towards the camera
    //          (a point light: its intensity); c.raster where it lands.
    //          Pitfalls: no cosine at a point light (onSurface); a background y_0 is a direction,
    //          not a point: it cannot be joined to the pinhole (Eq. 7.12).
    (void)scene; (void)y; (void)s; (void)z0;
    return PS_TODO("lesson 07: connectCamera", Connection());
}

Connection connectLight(const Scene& scene, const PathVertex* z, int t, float uLight, const Vec2& uPos) {
    // TODO(07) Eq. 7.2, 7.4 (s = 1): next-event estimation from z_{t-1} as in lesson 2: a light
    //          chosen with scene.selectLight(uLight, ...), a point on it with sampleLight(..., uPos),
    //          stored as the new light vertex c.sampledLight (lesson 6's lightVertex of the light
    //          sample; pdfFwd = pdfLightOrigin, beta = 1 / pdfFwd); C* = beta_y Le G f_z beta_z
    //          with lesson 6's geometryTerm, after the shadow ray. Not valid at a background
    //          z_{t-1}, nor where the light sample has no density (pdfA and pdfW both 0).
    //          Pitfalls: y_0's density is the light subpath's (with the light's selection
    //          probability), not the light sample's; a shadow ray to a point light or the
    //          background is not spawnRayTo(a surface point).
    (void)scene; (void)z; (void)t; (void)uLight; (void)uPos;
    return PS_TODO("lesson 07: connectLight", Connection());
}

Connection connectVertices(const Scene& scene, const PathVertex* y, int s, const PathVertex* z, int t) {
    // TODO(07) Eq. 7.2, 7.4, 7.6 (s, t >= 2): the two endpoints joined by a shadow ray:
    //          C* = beta_y f_y G f_z beta_z with lesson 6's geometryTerm, each f and the four
    //          reverse pdfs (c.rev, as connectionPdfs would give them) from one scatteringAt per
    //          endpoint; valid = not black and unoccluded.
    //          Pitfalls: each endpoint's light side and camera side (y_{s-1}'s camera side is
    //          z_{t-1}); a background end cannot be joined; two coincident points (direction 0)
    //          give nothing, not NaN.
    (void)scene; (void)y; (void)s; (void)z; (void)t;
    return PS_TODO("lesson 07: connectVertices", Connection());
}

}  // namespace ps
