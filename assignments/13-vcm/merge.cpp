// Lesson 13 — merging at a camera vertex: lesson 8's density estimate over the light vertices of
// every light subpath of the iteration (Eq. 13.3), each merge weighted against every connection
// and every other merge of the path it stands for (Eq. 13.11). Interface: lessons/13-vcm/vcm.h.
// Equation numbers refer to lessons/13-vcm/README.md.
#include "13-vcm/vcm.h"
#include "todo.h"

namespace ps {

ReversePdfs mergePdfs(const Scene& scene, const PathVertex* y, int e, const PathVertex* z, int f) {
    // TODO(13) Eq. 13.10: the four densities at the junction of the merged path, as lesson 7's
    //          connection (e, f + 1) of y_0 .. y_{e-1} and z_f .. z_0 names them: lightEnd = the
    //          camera side's density of y_{e-1} (the camera vertex's BSDF sampling the light's
    //          arriving direction, per unit area at y_{e-1} as seen from y_e), lightPrev = y_{e-2}'s
    //          stored reverse density (0 if e < 2), cameraEnd = the light side's density of the
    //          merge vertex (y_e's own), cameraPrev = the light side's density of z_{f-1} (the
    //          camera vertex's BSDF arrived at from the light's direction).
    //          Pitfalls: pdfBSDF(m, n, towards where the walk came from, towards where it goes);
    //          the camera vertex's material and normal; lesson 6's pdfSolidAngleToArea.
    (void)scene; (void)y; (void)e; (void)z; (void)f;
    return PS_TODO("lesson 13: mergePdfs", ReversePdfs());
}

Color mergeAtVertex(const Scene& scene, const Subpath& camera, const MergeSums& cameraSums, int f,
                    const LightVertices& lights, const MergeOptions& opt, MergeRecorder* recorder) {
    // TODO(13) Eq. 13.3, 13.11: every light vertex y_e within opt.radius of z_f
    //          (lightVerticesWithin), except those whose merged path would have more than
    //          opt.maxDepth bounces: its unweighted value C*_VM (Eq. 13.3, N = opt.lightPaths)
    //          and its weight: 1 in Ppm mode, else misWeightMerge of the merged path read as the
    //          connection (e, f + 1): its mergePdfs, lesson 7's misWeightRecursive, and
    //          mergeTerms. Report each merge to the recorder (if any); return the weighted sum.
    //          Pitfalls: the search takes the squared radius; the merged path has e + f + 1
    //          vertices; the BSDF is the camera vertex's, the arriving direction the light's.
    (void)scene; (void)camera; (void)cameraSums; (void)f; (void)lights; (void)opt; (void)recorder;
    return PS_TODO("lesson 13: mergeAtVertex", Color(0.0f));
}

}  // namespace ps
