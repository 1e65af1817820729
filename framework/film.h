// The film: accumulates the images of successive iterations in double, with a per-pixel
// variance estimate, and counts the samples that were NaN or Inf (they are left out of the
// image, counted, and reported at the end of every render).
#pragma once
#include <cstdint>
#include <utility>
#include <vector>
#include "image.h"

namespace ps {

struct SampleStats {
    uint64_t nan = 0, inf = 0;  // samples rejected because some channel was NaN / +-Inf
    uint64_t rays = 0;          // rays traced
    SampleStats& operator+=(const SampleStats& o) {
        nan += o.nan;
        inf += o.inf;
        rays += o.rays;
        return *this;
    }
    uint64_t bad() const { return nan + inf; }
};

// A sample enters the image only if it is finite; otherwise it is counted and becomes 0.
inline Color checkSample(const Color& c, SampleStats& stats) {
    if (isFinite(c)) return c;
    if (hasNaN(c)) ++stats.nan;
    else ++stats.inf;
    return Color(0.0f);
}

class Film {
public:
    Film(int width = 0, int height = 0)
        : width_(width), height_(height), sum_(size_t(width) * height), sumSq_(size_t(width) * height) {}
    int width() const { return width_; }
    int height() const { return height_; }
    int iterations() const { return iterations_; }

    // Adds one iteration's image (the estimate of that iteration alone).
    void addIteration(const Image& iteration);
    // Mean over iterations: the rendered image.
    Image mean() const;
    // Per pixel and channel: the estimated variance of the mean, s^2 / n.
    Image varianceOfMean() const;

private:
    int width_, height_, iterations_ = 0;
    std::vector<DColor> sum_, sumSq_;
};

// Splats for one iteration of a light-path integrator. Each task (a fixed batch of light
// paths, whatever thread runs it) appends to its own list; resolve() adds the lists in task
// order, so the image is the same for any number of threads.
class SplatBuffer {
public:
    SplatBuffer(int width, int height, size_t tasks) : width_(width), height_(height), lists_(tasks) {}
    // Adds c at raster position (x, y) in [0,width) x [0,height). Non-finite values are counted.
    void splat(size_t task, const Vec2& raster, const Color& c, SampleStats& stats);
    // Adds every splat into img (tasks in order) and empties the lists.
    void resolve(Image& img);

private:
    // Each list in a cache line of its own: tasks next to each other run on different threads at
    // once, and lists sharing a line would make every splat move that line between the cores
    // (false sharing; bench/render_bench measures the 2-thread speed-up).
    struct alignas(64) List {
        std::vector<std::pair<uint32_t, Color>> splats;
    };
    int width_, height_;
    std::vector<List> lists_;
};

// Where a light path's contributions go: one task's list of the iteration's splat buffer
// (framework/tasks.h), with the factor 1/N of the N light paths of the iteration (each light
// path is one estimate of the whole image). Without a buffer the splats are dropped (scale still
// says 1/N).
struct SplatTarget {
    SplatBuffer* buffer = nullptr;
    size_t task = 0;
    SampleStats* stats = nullptr;
    float scale = 1.0f;  // 1 / (light paths per iteration)
    void add(const Vec2& raster, const Color& c) const {
        if (buffer) buffer->splat(task, raster, c * scale, *stats);
    }
};

}  // namespace ps
