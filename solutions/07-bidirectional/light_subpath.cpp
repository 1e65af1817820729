// Lesson 7 — the light subpath y_0 .. y_{s-1} (Eq. 7.1, 7.3). Interface:
// lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void lightSubpath(const Scene& scene, Rng& rng, int maxDepth, Heuristic h, Subpath& path) {
    //! TODO(07) Eq. 7.1, 7.3: lesson 5's light walk (startLightPath, sampleAdjointBSDF, Russian
    //!          roulette) storing y_0 .. y_{s-1}, at most maxDepth + 1 vertices: y_0 = start.y0 with
    //!          onLight, pointLight, infinite (sp.n towards the background, as lesson 6's
    //!          backgroundVertex), pdfFwd = pdfLightOrigin, beta = 1 / pdfFwd; each hit a
    //!          surfaceVertex with beta (from start.beta on), pdfFwd (pdfLightToward for y_1, else
    //!          pdfScatter Importance); then y_{i-2}.pdfRev (pdfScatter Radiance) and
    //!          updateMisSum(path, i, h) for every i.
    //!          Pitfalls: pdfFwd from the vertices' positions (the same function the weights use),
    //!          not the sample's pdf; a reference into `path` dies at push_back.
    //! STUB (void)scene; (void)rng; (void)maxDepth; (void)h;
    //! STUB path.clear();
    //! STUB (void)PS_TODO("lesson 07: lightSubpath", 0);
    //! BEGIN
    path.clear();
    const LightPathStart start = startLightPath(scene, rng.uniform(), rng.uniform2(), rng.uniform2());
    if (!start.valid) return;
    const Light& light = scene.lights[size_t(start.light)];
    PathVertex y0;
    y0.sp = start.y0;
    y0.onLight = true;
    y0.pointLight = light.isDelta();
    y0.infinite = light.isInfinite();
    if (y0.infinite) y0.sp.n = -start.ray.d;   // towards the background (lesson 6's convention)
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
        PathVertex v = surfaceVertex(scene, sp);
        v.beta = beta;
        const PathVertex& prev = path.back();
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
