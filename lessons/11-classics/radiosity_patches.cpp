// Lesson 11 — patch averages (plumbing: read it, nothing to write here): the mean radiance
// leaving each quad, from a radiosity solution and from lesson 3's path tracer, which the graded
// tests and the figures compare (radiosity.h).
#include <cmath>
#include "03-path-tracing/pathtracer.h"
#include "11-classics/radiosity.h"
#include "tasks.h"

namespace ps {

std::vector<Color> patchRadiance(const ElementMesh& mesh, const RadiositySolution& s) {
    const size_t quads = mesh.nu() > 0 ? size_t(mesh.size() / (mesh.nu() * mesh.nv())) : 0;
    std::vector<DColor> sum(quads, DColor(0.0));
    std::vector<double> area(quads, 0.0);
    const bool started = s.B.size() == size_t(mesh.size());
    for (int e = 0; e < mesh.size(); ++e) {
        const size_t q = size_t(mesh[e].quad);
        area[q] += mesh[e].area;
        if (started) sum[q] += DColor(s.B[size_t(e)]) * double(mesh[e].area);
    }
    std::vector<Color> L(quads);
    for (size_t q = 0; q < quads; ++q) L[q] = Color(sum[q] / (area[q] * double(kPi)));
    return L;
}

std::vector<PatchEstimate> patchRadiancePT(const Scene& scene, int samples, int maxDepth, uint64_t seed) {
    std::vector<PatchEstimate> out;
    SampleStats stats;
    for (size_t qi = 0; qi < scene.quads.size(); ++qi) {
        const Quad& q = scene.quads[qi];
        const Triangle t[2] = {scene.triangles[scene.prims[q.prim].index],
                               scene.triangles[scene.prims[q.prim + 1].index]};
        const float p0 = t[0].area() / (t[0].area() + t[1].area());
        const size_t tasks = size_t(taskCount(samples));
        std::vector<DColor> sum(tasks, DColor(0.0)), sumSq(tasks, DColor(0.0));
        runTasks(TaskLoop(samples, seed, uint32_t(qi)), stats, [&](int, Rng& rng, Task& task) {
            Vec2 u = rng.uniform2();
            const int k = u.x < p0 ? 0 : 1;
            u.x = k == 0 ? u.x / p0 : (u.x - p0) / (1.0f - p0);
            u.x = std::min(u.x, 0x1.fffffep-1f);
            const Vec2 b = sampleUniformTriangle(u);
            const Triangle& tri = t[k];
            const Vec3 x = (1.0f - b.x - b.y) * tri.p0 + b.x * tri.p1 + b.y * tri.p2;
            const Vec3 n = tri.normal();
            // From just off the front (8 times the framework's ray offset), straight at x.
            const float delta = tri.errScale() * 0x1p-16f;
            const Ray ray(x + delta * n, -n, 2.0f * delta);
            const DColor L(checkSample(LiMIS(scene, ray, rng, maxDepth), task.stats));
            sum[task.index] += L;
            sumSq[task.index] += L * L;
        });
        DColor s(0.0), s2(0.0);
        for (size_t k = 0; k < tasks; ++k) {  // in task order
            s += sum[k];
            s2 += sumSq[k];
        }
        const double n = samples;
        PatchEstimate e;
        e.mean = s / n;
        const DColor var = glm::max(DColor(0.0), (s2 - s * s / n) / (n - 1.0));
        e.stdError = glm::sqrt(var / n);
        out.push_back(e);
    }
    return out;
}

}  // namespace ps
