// Lesson 13 — the per-technique images of vcm and its special cases, Veach's pyramid with merging
// rows (`pathspace pyramid SCENE --algo vcm`; plumbing: read it, nothing to write here).
//
// Each iteration is the integrator's (vcm_integrator.cpp): the light pass, the tree, the radius
// r_i, then vcmSample per pixel, here with recorders that put every connection (s, t) and every
// merge M(e, f) into its own cell. A row k holds the techniques of the paths with k edges: the
// connections s + t = k + 1 and the merges e + f = k (light vertex y_e with camera vertex z_f,
// the merged path x_0 .. x_k with the merge at x_e). Its weighted cells add up to what vcm renders
// for those paths; an unweighted merge cell is the merge's estimate alone (biased by the radius,
// README section 1.2), the same paths as its row's connections.
#include <omp.h>
#include <algorithm>
#include <string>
#include "13-vcm/vcm.h"
#include "tasks.h"

namespace ps {
namespace {

// Connection cells of row k: every s = 0 .. k + 1, or s = 0 alone in the photon-mapping modes.
int connectionCells(VcmMode mode, int k) { return mode == VcmMode::Vcm || mode == VcmMode::Bpt ? k + 2 : 1; }

std::vector<TechniqueRow> vcmLayout(VcmMode mode, int maxLength) {
    std::vector<TechniqueRow> rows;
    for (int k = 1; k <= maxLength; ++k) {
        TechniqueRow row;
        row.label = "k=" + std::to_string(k);
        for (int s = 0; s < connectionCells(mode, k); ++s) {
            const std::string a = std::to_string(s), b = std::to_string(k + 1 - s);
            row.cells.push_back({a + "-" + b, "(" + a + "," + b + ")", {}, {}});
        }
        if (mode != VcmMode::Bpt)
            for (int e = 1; e < k; ++e) {
                const std::string a = std::to_string(e), b = std::to_string(k - e);
                row.cells.push_back({"m" + a + "-" + b, "M(" + a + "," + b + ")", {}, {}});
            }
        rows.push_back(row);
    }
    return rows;
}

// What one pixel sample's techniques gave, kept in its task's list and added to the cells after
// the iteration in task order: a t <= 1 connection lands in any pixel, so adding at once would
// make the images depend on the thread count. NaN/Inf values are counted and left out.
struct CellValue {
    int row, cell, x, y;
    Color unweighted, weighted;
};

struct PyramidRecorder : TechniqueRecorder, MergeRecorder {
    VcmMode mode = VcmMode::Vcm;
    int maxLength = 0, width = 0, height = 0;
    int x = 0, y = 0;  // the sample's pixel (merges land there)
    std::vector<CellValue>* list = nullptr;
    SampleStats* stats = nullptr;

    void keep(int k, int cell, int px, int py, const Color& unweighted, const Color& weighted) {
        if (k < 1 || k > maxLength) return;
        if (!isFinite(unweighted) || !isFinite(weighted)) {
            checkSample(isFinite(unweighted) ? weighted : unweighted, *stats);
            return;
        }
        list->push_back(
            {k - 1, cell, std::clamp(px, 0, width - 1), std::clamp(py, 0, height - 1), unweighted, weighted});
    }
    void add(int s, int t, const Vec2& raster, const Color& unweighted, const Color& weighted) override {
        keep(s + t - 1, s, static_cast<int>(raster.x), static_cast<int>(raster.y), unweighted, weighted);
    }
    void add(const LightVertexRef& light, int f, const Color& unweighted, float weight) override {
        const int e = int(light.index), k = e + f;
        keep(k, connectionCells(mode, k) + e - 1, x, y, unweighted, unweighted * weight);
    }
};

TechniquePyramid renderVcmTechniques(const Scene& scene, const TechniqueImagesOptions& o, const VcmOptions& opt) {
    const int w = scene.camera.width(), h = scene.camera.height(), pixels = w * h;
    if (o.threads > 0) omp_set_num_threads(o.threads);
    Scene limited = scene;  // row k needs paths of k edges at most
    limited.settings.maxDepth = std::min(scene.settings.maxDepth, o.maxLength - 1);
    TechniquePyramid p;
    p.rows = vcmLayout(opt.mode, o.maxLength);
    for (TechniqueRow& row : p.rows)
        for (TechniqueCell& cell : row.cells) cell.unweighted = cell.weighted = Image(w, h);
    const bool lightPass = opt.mode != VcmMode::Bpt;
    LightVertices lights;
    std::vector<std::vector<CellValue>> lists(static_cast<size_t>(taskCount(pixels)));
    for (int it = 0; it < o.spp; ++it) {
        const MergeOptions m = vcmMergeOptions(opt, limited, uint32_t(it), pixels);
        if (lightPass) {
            traceLightSubpaths(limited, pixels, opt.heuristic, o.seed, uint32_t(it), lights, p.stats);
            buildLightVertexTree(lights);
        }
        TaskLoop loop(pixels, o.seed, uint32_t(it));  // no SplatBuffer: vcmSample's own splats are not wanted
        loop.splatScale = 1.0f / static_cast<float>(pixels);
        runTasks(loop, p.stats, [&](int pixel, Rng& rng, Task& task) {
            PyramidRecorder recorder;
            recorder.mode = opt.mode;
            recorder.maxLength = o.maxLength;
            recorder.width = w;
            recorder.height = h;
            recorder.x = pixel % w;
            recorder.y = pixel / w;
            recorder.list = &lists[task.index];
            recorder.stats = &task.stats;
            const Vec2 raster = jitteredRaster(pixel, w, rng);
            vcmSample(limited, raster, rng, opt, m, lightPass ? &lights : nullptr, uint32_t(pixel), task.splat,
                      {&recorder, &recorder});
        });
        for (auto& list : lists) {
            for (const CellValue& v : list) {
                TechniqueCell& cell = p.rows[size_t(v.row)].cells[size_t(v.cell)];
                cell.unweighted.at(v.x, v.y) += v.unweighted;
                cell.weighted.at(v.x, v.y) += v.weighted;
            }
            list.clear();
        }
    }
    const float inv = 1.0f / static_cast<float>(std::max(o.spp, 1));
    for (TechniqueRow& row : p.rows)
        for (TechniqueCell& cell : row.cells)
            for (size_t q = 0; q < cell.unweighted.pixels.size(); ++q) {
                cell.unweighted.pixels[q] *= inv;
                cell.weighted.pixels[q] *= inv;
            }
    return p;
}

}  // namespace

TechniqueRenderer vcmTechniqueRenderer(const VcmOptions& opt) {
    TechniqueRenderer r;
    r.layout = [mode = opt.mode](int maxLength) { return vcmLayout(mode, maxLength); };
    r.render = [opt](const Scene& scene, const TechniqueImagesOptions& o) {
        return renderVcmTechniques(scene, o, opt);
    };
    return r;
}

}  // namespace ps
