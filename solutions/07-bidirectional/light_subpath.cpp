// Lesson 7 — the light subpath y_0 .. y_{s-1} (Eq. 7.1, 7.3). Interface:
// lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void lightSubpath(const Scene& scene, Rng& rng, int maxDepth, Heuristic h, Subpath& path) {
    //! TODO(07) The light subpath (Eq. 7.1, 7.3), like lesson 5's traceLightPath without the
    //!          camera connections:
    //!          1. path.clear(); start = startLightPath(scene, rng.uniform(), rng.uniform2(),
    //!             rng.uniform2()); stop if not valid.
    //!          2. y_0: kind Light, sp = start.y0, light = start.light, deltaPosition = the light
    //!             is a point light, infinite = it is the background (then sp.n = the direction
    //!             of start.ray), pdfFwd = pdfLightOrigin(scene, y_0), beta = 1 / pdfFwd.
    //!          3. beta = start.beta, throughput = 1, ray = start.ray; for bounces = 1 .. maxDepth:
    //!             a. scene.intersect(ray, sp), stop on a miss. Append y_i: kind Surface, sp,
    //!                beta, delta = material.isDelta(); pdfFwd = pdfLightToward(y_0, y_1) for
    //!                i = 1, else pdfScatter(scene, &y_{i-2}, y_{i-1}, y_i, Transport::Importance):
    //!                the density of the direction sampled at y_{i-1}, evaluated from the vertices'
    //!                positions with the same function the MIS weights use (after a delta vertex:
    //!                its lobe's coefficient, Eq. 7.7a).
    //!             b. If i >= 2: y_{i-2}.pdfRev = pdfScatter(scene, &y_i, y_{i-1}, y_{i-2},
    //!                Transport::Radiance) (the camera's way). Then updateMisSum(path, i, h).
    //!             c. Stop if bounces == maxDepth. sampleAdjointBSDF(m, sp.n, -ray.d,
    //!                rng.uniform2(), rng.uniform(), s); stop if false; beta and throughput *= s.weight, stop if
    //!                black; Russian roulette with survivalProbability(throughput, bounces)
    //!                as in lesson 5; ray = scene.spawnRay(sp, s.wi).
    //!          Call updateMisSum(path, i, h) for i = 0 and 1 as well (they are 0).
    //!          Careful: take references into `path` only after push_back (it may reallocate).
    //! STUB (void)scene; (void)rng; (void)maxDepth; (void)h;
    //! STUB path.clear();
    //! STUB (void)PS_TODO("lesson 07: lightSubpath", 0);
    //! BEGIN
    path.clear();
    const LightPathStart start = startLightPath(scene, rng.uniform(), rng.uniform2(), rng.uniform2());
    if (!start.valid) return;
    const Light& light = scene.lights[size_t(start.light)];
    SubpathVertex y0;
    y0.kind = VertexKind::Light;
    y0.sp = start.y0;
    y0.light = start.light;
    y0.deltaPosition = light.isDelta();
    y0.infinite = light.isInfinite();
    if (y0.infinite) y0.sp.n = start.ray.d;
    y0.pdfFwd = pdfLightOrigin(scene, y0);
    if (!(y0.pdfFwd > 0.0f)) return;
    y0.beta = Color(1.0f / y0.pdfFwd);
    path.push_back(y0);
    updateMisSum(path, 0, h);

    Color beta = start.beta, throughput(1.0f);
    Ray ray = start.ray;
    for (int bounces = 1; bounces <= maxDepth; ++bounces) {
        SurfacePoint sp;
        if (!scene.intersect(ray, sp)) break;
        const Material& m = scene.materials[size_t(sp.material)];
        SubpathVertex v;
        v.kind = VertexKind::Surface;
        v.sp = sp;
        v.beta = beta;
        v.delta = m.isDelta();
        v.light = sp.light;
        const SubpathVertex& prev = path.back();
        if (bounces == 1) v.pdfFwd = pdfLightToward(scene, prev, v);
        else v.pdfFwd = pdfScatter(scene, &path[path.size() - 2], prev, v, Transport::Importance);
        path.push_back(v);
        const size_t i = path.size() - 1;
        if (i >= 2) path[i - 2].pdfRev = pdfScatter(scene, &path[i], path[i - 1], path[i - 2], Transport::Radiance);
        updateMisSum(path, i, h);

        if (bounces == maxDepth) break;
        BSDFSample s;
        if (!sampleAdjointBSDF(m, sp.n, -ray.d, rng.uniform2(), rng.uniform(), s)) break;
        beta *= s.weight;
        throughput *= s.weight;
        if (isBlack(beta)) break;
        const float q = survivalProbability(throughput, bounces);
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
