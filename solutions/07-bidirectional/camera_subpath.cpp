// Lesson 7 — the camera subpath z_0 .. z_{t-1} (Eq. 7.1, 7.3): lesson 3's walk, storing its
// vertices. Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to
// lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void cameraSubpath(const Scene& scene, Rng& rng, const Vec2& raster, int maxDepth, Heuristic h, Subpath& path,
                   const CameraVertexVisitor& visit) {
    //! TODO(07) The camera subpath through raster (Eq. 7.1, 7.1a, 7.3), as cameraSubpath in bpt.h states it, each vertex's
    //!          densities by bpt.h's conventions and its misSum (Eq. 7.9). Pitfalls (README 6): pdfFwd evaluated from
    //!          the positions, not the walk's sample pdf; pdfRev of z_{i-2}, known once z_i exists.
    //! STUB (void)scene; (void)rng; (void)raster; (void)maxDepth; (void)h; (void)visit;
    //! STUB path.clear();
    //! STUB (void)PS_TODO("lesson 07: cameraSubpath", 0);
    //! BEGIN
    path.clear();
    const Camera& camera = scene.camera;
    PathVertex z0 = cameraVertex(scene, camera.samplePoint(rng));
    z0.beta = Color(1.0f);
    z0.pdfFwd = camera.pdfPoint();
    path.push_back(z0);
    updateMisSum(path, 0, h);

    const Ray ray = camera.generateRay(raster, z0.p());
    WalkOptions opt(maxDepth);
    opt.continuation = [&scene](const WalkVertex& v, Rng& r) { return subpathContinuation(scene, v, r); };
    cameraWalk(scene, ray, rng, opt, [&](const WalkVertex& w) {
        if (!w.hit && scene.background < 0) return false;
        PathVertex v = w.hit ? surfaceVertex(scene, w.sp) : backgroundVertex(scene, -w.wo);
        v.beta = w.beta;
        v.pdfFwd =
            pdfScatter(scene, path.size() >= 2 ? &path[path.size() - 2] : nullptr, path.back(), v, Transport::Radiance);
        path.push_back(v);
        const size_t k = path.size() - 1;
        if (k >= 2) path[k - 2].pdfRev = pdfScatter(scene, &path[k], path[k - 1], path[k - 2], Transport::Importance);
        updateMisSum(path, k, h);
        return !visit || visit(path);
    });
    //! END
}

}  // namespace ps
