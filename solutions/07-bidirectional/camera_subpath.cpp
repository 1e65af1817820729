// Lesson 7 — the camera subpath z_0 .. z_{t-1} (Eq. 7.1, 7.3). Interface:
// lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void cameraSubpath(const Scene& scene, Rng& rng, const Vec2& raster, int maxDepth, Heuristic h, Subpath& path) {
    //! TODO(07) Eq. 7.1, 7.3: lesson 3's camera walk (sampleBSDF Radiance, Russian roulette)
    //!          storing z_0 .. z_{t-1}: z_0 = cameraVertex (beta 1, pdfFwd 1: a delta position),
    //!          each hit a surfaceVertex, a miss with a background a backgroundVertex that ends it;
    //!          every z_i with beta, pdfFwd = pdfScatter Radiance, then z_{i-2}.pdfRev =
    //!          pdfScatter Importance and updateMisSum(path, i, h). At most maxDepth + 2 vertices.
    //!          Pitfall: pdfFwd from the positions, not the sample's s.pdf (the ray starts off the
    //!          surface; the weights would no longer sum to 1).
    //! STUB (void)scene; (void)rng; (void)raster; (void)maxDepth; (void)h;
    //! STUB path.clear();
    //! STUB (void)PS_TODO("lesson 07: cameraSubpath", 0);
    //! BEGIN
    path.clear();
    const Camera& camera = scene.camera;
    PathVertex z0 = cameraVertex(scene);
    z0.beta = Color(1.0f);
    z0.pdfFwd = 1.0f;
    path.push_back(z0);
    updateMisSum(path, 0, h);

    Ray ray = camera.generateRay(raster);
    Color beta(1.0f), throughput(1.0f);
    for (int i = 1; i <= maxDepth + 1; ++i) {
        SurfacePoint sp;
        const bool hit = scene.intersect(ray, sp);
        if (!hit && scene.background < 0) break;
        PathVertex v = hit ? surfaceVertex(scene, sp) : backgroundVertex(scene, ray.d);
        v.beta = beta;
        v.pdfFwd = pdfScatter(scene, path.size() >= 2 ? &path[path.size() - 2] : nullptr, path.back(), v,
                              Transport::Radiance);
        path.push_back(v);
        const size_t k = path.size() - 1;
        if (k >= 2) path[k - 2].pdfRev = pdfScatter(scene, &path[k], path[k - 1], path[k - 2], Transport::Importance);
        updateMisSum(path, k, h);
        if (!hit || i == maxDepth + 1) break;

        const Material& m = scene.materials[size_t(sp.material)];
        BSDFSample s;
        if (!sampleBSDF(m, sp.n, -ray.d, rng.uniform2(), rng.uniform(), Transport::Radiance, s)) break;
        beta *= s.weight;
        throughput *= s.weight;
        if (isBlack(beta)) break;
        const float q = survivalProbability(throughput, i);
        if (q < 1.0f) {
            if (rng.uniform() >= q) break;
            beta /= q;
            throughput /= q;
        }
        ray = scene.spawnRay(sp, s.wi);
    }
    //! END
}

}  // namespace ps
