// Lesson 7 — the camera subpath z_0 .. z_{t-1} (Eq. 7.1, 7.3): lesson 3's walk, storing its
// vertices. Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to
// lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void cameraSubpath(const Scene& scene, Rng& rng, const Vec2& raster, int maxDepth, Heuristic h, Subpath& path,
                   const CameraVertexVisitor& visit) {
    // TODO(07) Eq. 7.1, 7.3: z_0 = cameraVertex(scene, camera.samplePoint(rng)) (beta 1, pdfFwd
    //          camera.pdfPoint(): 1 for the pinhole, a delta position; or a camera model's point),
    //          then lesson 3's cameraWalk from camera.generateRay(raster, z_0's position) with a
    //          visitor that stores every
    //          vertex it is shown: a hit as a surfaceVertex, a miss as a backgroundVertex if there
    //          is a background (none: end the walk), each with the walk's beta, pdfFwd =
    //          pdfScatter Radiance, then z_{i-2}.pdfRev = pdfScatter Importance and
    //          updateMisSum(path, i, h), then hand the subpath to visit (if set: its false ends the
    //          walk). At most maxDepth + 2 vertices.
    //          Pitfall: pdfFwd from the positions, not the walk's pdfPrev (the ray starts off the
    //          surface; the weights would no longer sum to 1).
    (void)scene; (void)rng; (void)raster; (void)maxDepth; (void)h; (void)visit;
    path.clear();
    (void)PS_TODO("lesson 07: cameraSubpath", 0);
}

}  // namespace ps
