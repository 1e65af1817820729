// Lesson 13 — merging at a camera vertex: lesson 8's density estimate over the light vertices of
// every light subpath of the iteration (Eq. 13.3), each merge weighted against every connection
// and every other merge of the path it stands for (Eq. 13.11). Interface: lessons/13-vcm/vcm.h.
// Equation numbers refer to lessons/13-vcm/README.md.
#include "13-vcm/vcm.h"
#include "todo.h"

namespace ps {

ReversePdfs mergePdfs(const Scene& scene, const PathVertex* y, int e, const PathVertex* z, int f) {
    // TODO(13) The merge's four junction densities, per unit area, in the roles vcm.h and README 1.5 give
    //          them. Pitfalls (README 6): the BSDF is the camera vertex's, the arriving direction the light's.
    (void)scene; (void)y; (void)e; (void)z; (void)f;
    return PS_TODO("lesson 13: mergePdfs", ReversePdfs());
}

Color mergeAtVertex(const Scene& scene, const Subpath& camera, const MergeSums& cameraSums, int f,
                    const LightVertices& lights, const MergeOptions& opt, MergeRecorder* recorder) {
    // TODO(13) The sum of C*_VM w_VM (Eq. 13.3, 13.11) over the light vertices merged with z_f (vcm.h; w = 1 for
    //          Ppm), each merge reported to the recorder if any. Pitfalls (README 6): the search takes r^2; the
    //          merged path has e + f + 1 vertices and the same depth limit as a connection.
    (void)scene; (void)camera; (void)cameraSums; (void)f; (void)lights; (void)opt; (void)recorder;
    return PS_TODO("lesson 13: mergeAtVertex", Color(0.0f));
}

}  // namespace ps
