// Lesson 7 — joining a light and a camera subpath: technique (s, t) (Eq. 7.2, 7.4) and the
// reverse pdfs the connection creates (Eq. 7.6). Interface: lessons/07-bidirectional/bpt.h.
// Equation numbers refer to lessons/07-bidirectional/README.md.
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

Connection connect(const Scene& scene, const Subpath& light, const Subpath& camera, int s, int t, float uLight,
                   const Vec2& uPos) {
    // TODO(07) Eq. 7.2, 7.4: the unweighted contribution C*_{s,t} = beta_y f_y G f_z beta_z with
    //          lesson 6's geometryTerm, for s = 0 (z_{t-1} emits), t = 1 (connectToCamera), s = 1
    //          (a fresh sampleLight into c.sampledLight, pdfFwd = pdfLightOrigin, beta = 1 / pdfFwd)
    //          and s, t >= 2, each after its shadow ray (s = 1: as lesson 2's next-event
    //          estimation); valid = not black and unoccluded; then rev = connectionPdfs.
    //          Pitfalls: f_x = evalBSDF(m, n, camera-side direction, light-side direction); s >= 1
    //          never joins at a specular or background endpoint; t = 1 sets c.sampledLight =
    //          light[0] too (the MIS reads y from it whenever s = 1); the background y_0's sp.n
    //          points towards the background (ls.wi).
    (void)scene; (void)light; (void)camera; (void)s; (void)t; (void)uLight; (void)uPos;
    return PS_TODO("lesson 07: connect", Connection());
}

}  // namespace ps
