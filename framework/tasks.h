// One parallel iteration, written once for every integrator: the work of an iteration is a
// list of items (the pixels, or the light paths), cut into tasks of kItemsPerTask consecutive
// items that the threads take in any order. Nothing that reaches the image depends on which
// thread ran a task or when:
//   - item i of iteration k draws its random numbers from taskRng(seed, k, i) only;
//   - each task has its own SampleStats (NaN/Inf samples, rays) and its own list in the
//     iteration's SplatBuffer; the lists are added to the image in task order after the loop,
//     and the counts too;
//   - a pixel's own value is written only by the item of that pixel.
// So an image is bit-identical for any number of threads. Every integrator uses renderPixelTasks
// or renderLightPathTasks; runTasks is the loop both are built on.
#pragma once
#include <cstdint>
#include <functional>
#include "camera.h"
#include "film.h"
#include "rng.h"

namespace ps {

// Items per task: fixed, so that the tasks (and their splat lists) are the same for any
// number of threads.
constexpr int kItemsPerTask = 64;

// What one task of an iteration owns.
struct Task {
    size_t index = 0;   // items [index * kItemsPerTask, (index + 1) * kItemsPerTask)
    SampleStats stats;  // this task's NaN/Inf samples and rays
    SplatTarget splat;  // this task's list of the iteration's SplatBuffer (none: splats are dropped)
};

// One iteration's task loop: its items, the seed and iteration their generators derive from, and
// (optionally) the splat buffer the tasks' lists belong to, with the factor of every splat.
struct TaskLoop {
    TaskLoop(int items_, uint64_t seed_, uint32_t iteration_) : items(items_), seed(seed_), iteration(iteration_) {}
    int items = 0;
    uint64_t seed = 0;
    uint32_t iteration = 0;
    SplatBuffer* splats = nullptr;  // one list per task (taskCount(items)); nullptr: splats are dropped
    float splatScale = 1.0f;        // task.splat.scale: the factor every splat carries
};

// item(i, rng, task) for every i in [0, loop.items), rng = taskRng(loop.seed, loop.iteration, i),
// in parallel tasks. With a SplatBuffer, task.splat adds to the task's own list with the factor
// splatScale; the caller resolves the buffer. The tasks' counts are added to stats (rays: every
// ray the threads traced during the loop).
using TaskItem = std::function<void(int item, Rng& rng, Task& task)>;
void runTasks(const TaskLoop& loop, SampleStats& stats, const TaskItem& item);

// The number of tasks of an iteration of `items` items.
inline int taskCount(int items) { return (items + kItemsPerTask - 1) / kItemsPerTask; }

// One sample per pixel: out.pixels[pixel] = sample(pixel, rng, task), NaN/Inf counted and left
// out (checkSample). With splatting, task.splat adds anywhere in the image with the factor
// 1 / (width * height) (as many light paths as pixels), after the pixels.
using PixelSample = std::function<Color(int pixel, Rng& rng, Task& task)>;
void renderPixelTasks(uint64_t seed, uint32_t iteration, Image& out, SampleStats& stats, bool splatting,
                      const PixelSample& sample);

// N = width * height light paths (as many as a path tracer's camera rays): path(i, rng, task)
// adds what path i sends to the camera through task.splat, which carries the factor 1/N.
using LightPathSample = std::function<void(int path, Rng& rng, Task& task)>;
void renderLightPathTasks(uint64_t seed, uint32_t iteration, Image& out, SampleStats& stats,
                          const LightPathSample& path);

// A uniformly jittered raster position in pixel `pixel` (row-major, `width` pixels a row): the
// first two random numbers of the pixel's generator, x's first.
inline Vec2 jitteredRaster(int pixel, int width, Rng& rng) {
    // Named, in this order: C++ evaluates a call's arguments in no fixed order.
    const float ux = rng.uniform();
    const float uy = rng.uniform();
    return Vec2(static_cast<float>(pixel % width) + ux, static_cast<float>(pixel / width) + uy);
}

// The camera ray through raster position `raster`: the pinhole's (no random number drawn), or a
// camera model's through its point drawn with the next two numbers of rng.
inline Ray cameraRay(const Camera& camera, const Vec2& raster, Rng& rng) {
    return camera.isPinhole() ? camera.generateRay(raster) : camera.sampleRay(raster, rng.uniform2());
}

}  // namespace ps
