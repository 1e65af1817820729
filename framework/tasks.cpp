#include "tasks.h"
#include <algorithm>
#include <vector>
#include "scene.h"

namespace ps {

void runTasks(const TaskLoop& loop, SampleStats& stats, const TaskItem& item) {
    const int items = loop.items;
    const int tasks = taskCount(items);
    std::vector<SampleStats> taskStats(static_cast<size_t>(tasks));
    uint64_t rays = 0;
#pragma omp parallel reduction(+ : rays)
    {
        rays += takeRayCount();  // traced by this thread before the loop (in prepare): this iteration's
#pragma omp for schedule(dynamic, 1)
        for (int t = 0; t < tasks; ++t) {
            Task task;
            task.index = static_cast<size_t>(t);
            task.splat = SplatTarget{loop.splats, task.index, &task.stats, loop.splatScale};
            const int end = std::min(items, (t + 1) * kItemsPerTask);
            for (int i = t * kItemsPerTask; i < end; ++i) {
                Rng rng = taskRng(loop.seed, loop.iteration, static_cast<uint32_t>(i));
                item(i, rng, task);
            }
            task.stats.rays += takeRayCount();
            taskStats[task.index] = task.stats;
        }
    }
    for (const SampleStats& s : taskStats) stats += s;  // in task order
    stats.rays += rays;
}

void renderPixelTasks(uint64_t seed, uint32_t iteration, Image& out, SampleStats& stats, bool splatting,
                      const PixelSample& sample) {
    const int pixels = out.width * out.height;
    SplatBuffer splats(out.width, out.height, splatting ? static_cast<size_t>(taskCount(pixels)) : 0);
    TaskLoop loop(pixels, seed, iteration);
    loop.splats = splatting ? &splats : nullptr;
    loop.splatScale = 1.0f / static_cast<float>(pixels);
    runTasks(loop, stats, [&](int pixel, Rng& rng, Task& task) {
        out.pixels[size_t(pixel)] = checkSample(sample(pixel, rng, task), task.stats);
    });
    splats.resolve(out);
}

void renderLightPathTasks(uint64_t seed, uint32_t iteration, Image& out, SampleStats& stats,
                          const LightPathSample& path) {
    const int paths = out.width * out.height;
    SplatBuffer splats(out.width, out.height, static_cast<size_t>(taskCount(paths)));
    TaskLoop loop(paths, seed, iteration);
    loop.splats = &splats;
    loop.splatScale = 1.0f / static_cast<float>(paths);
    runTasks(loop, stats, path);
    splats.resolve(out);
}

}  // namespace ps
