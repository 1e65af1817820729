// Lesson 7 — the camera subpath z_0 .. z_{t-1} (Eq. 7.1, 7.3). Interface:
// lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void cameraSubpath(const Scene& scene, Rng& rng, const Vec2& raster, int maxDepth, Heuristic h, Subpath& path) {
    //! TODO(07) The camera subpath (Eq. 7.1, 7.3), a random walk like lesson 3's:
    //!          1. path.clear(); z_0: kind Camera, sp.p = camera.position(), sp.n =
    //!             camera.forward(), deltaPosition = true, beta = 1, pdfFwd = 1 (the pinhole is
    //!             chosen with probability 1: a delta position); updateMisSum(path, 0, h).
    //!             ray = camera.generateRay(raster), beta = 1 (the pixel's estimate is the
    //!             radiance itself), throughput = 1.
    //!          2. For i = 1 .. maxDepth + 1:
    //!             a. On a miss: if the scene has a background (scene.background >= 0) append
    //!                z_i: kind Light, infinite, light = scene.background, sp.n = -ray.d, beta,
    //!                pdfFwd as in b. (per solid angle: convertToArea leaves it); then stop.
    //!             b. On a hit sp: z_i: kind Surface, sp, beta, light = sp.light, delta =
    //!                material.isDelta(), pdfFwd = pdfScatter(scene, &z_{i-2} (null for i = 1),
    //!                z_{i-1}, z_i, Transport::Radiance) (the camera walks against the light): evaluated from the positions with the function the MIS
    //!                weights use, not the sample's s.pdf (the ray starts off the surface, so the
    //!                two differ slightly, and the weights would no longer sum to 1).
    //!             For both: after appending, if i >= 2 set z_{i-2}.pdfRev = pdfScatter(scene,
    //!             &z_i, z_{i-1}, z_{i-2}, Transport::Importance) (the light's way); updateMisSum(path, i, h).
    //!             c. Stop if i == maxDepth + 1. sampleBSDF(m, sp.n, -ray.d, rng.uniform2(),
    //!                rng.uniform(), Transport::Radiance, s), stop if false; beta and throughput *= s.weight, stop if black;
    //!                Russian roulette with survivalProbability(throughput, i);
    //!                ray = scene.spawnRay(sp, s.wi).
    //! STUB (void)scene; (void)rng; (void)raster; (void)maxDepth; (void)h;
    //! STUB path.clear();
    //! STUB (void)PS_TODO("lesson 07: cameraSubpath", 0);
    //! BEGIN
    path.clear();
    const Camera& camera = scene.camera;
    SubpathVertex z0;
    z0.kind = VertexKind::Camera;
    z0.sp.p = camera.position();
    z0.sp.n = camera.forward();
    z0.deltaPosition = true;
    z0.beta = Color(1.0f);
    z0.pdfFwd = 1.0f;
    path.push_back(z0);
    updateMisSum(path, 0, h);

    Ray ray = camera.generateRay(raster);
    Color beta(1.0f), throughput(1.0f);
    for (int i = 1; i <= maxDepth + 1; ++i) {
        SurfacePoint sp;
        const bool hit = scene.intersect(ray, sp);
        SubpathVertex v;
        v.beta = beta;
        if (!hit) {
            if (scene.background < 0) break;
            v.kind = VertexKind::Light;
            v.infinite = true;
            v.light = scene.background;
            v.sp.n = -ray.d;
            v.pdfFwd = pdfScatter(scene, path.size() >= 2 ? &path[path.size() - 2] : nullptr, path.back(), v,
                                  Transport::Radiance);
        } else {
            v.kind = VertexKind::Surface;
            v.sp = sp;
            v.light = sp.light;
            v.delta = scene.materials[size_t(sp.material)].isDelta();
            v.pdfFwd = pdfScatter(scene, path.size() >= 2 ? &path[path.size() - 2] : nullptr, path.back(), v,
                                  Transport::Radiance);
        }
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
