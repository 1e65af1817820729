// Lesson 7 — the camera subpath z_0 .. z_{t-1} (Eq. 7.1, 7.3): lesson 3's walk, storing its
// vertices. Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to
// lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void cameraSubpath(const Scene& scene, Rng& rng, const Vec2& raster, int maxDepth, Heuristic h, Subpath& path,
                   const CameraVertexVisitor& visit) {
    // TODO(07) The camera subpath through raster (Eq. 7.1, 7.1a, 7.3), as cameraSubpath in bpt.h states it, each vertex's
    //          densities by bpt.h's conventions and its misSum (Eq. 7.9). Pitfalls (README 6): pdfFwd evaluated from
    //          the positions, not the walk's sample pdf; pdfRev of z_{i-2}, known once z_i exists.
    (void)scene; (void)rng; (void)raster; (void)maxDepth; (void)h; (void)visit;
    path.clear();
    (void)PS_TODO("lesson 07: cameraSubpath", 0);
}

}  // namespace ps
