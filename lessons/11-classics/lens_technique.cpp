// Lesson 11 — plumbing (nothing to write here): bidirectional path tracing's technique t = 0, one of
// lesson 7's extra techniques (bpt.h), which bptSample calls after its own (Eq. 11.16-11.18). With a
// thin lens, every light vertex y_m takes one more
// step (connectLens, yours), and where that step's ray meets the lens the path y_0 .. y_m z, s =
// m + 2, t = 0, is splatted where it lands, MIS-weighted against every other technique by lesson
// 7's own weights: the path is a light subpath that ends on the lens. Under `--paths` (lesson 7's
// BptOptions::techniqueFilter, filtered_bpt.cpp) the path y_0 .. y_m z is added only if it matches, with
// the lens point z as its E: tested after connectLens has drawn the step's numbers, so that every
// later step meets the same numbers whatever the expression (the images of a partition of the
// paths add up to bpt's, sample by sample). Interface: lessons/11-classics/thinlens.h.
#include "11-classics/thinlens.h"

namespace ps {

float lensMisWeight(const Scene& scene, const Subpath& light, int m, const LensConnection& c, Heuristic h,
                    bool recursive, Subpath* joined) {
    thread_local Subpath local;
    Subpath& x = joined ? *joined : local;
    x.assign(light.begin(), light.begin() + m + 1);
    if (m == 0) {  // connectLens's own light vertex replaces the subpath's y_0
        x[0] = c.light;
        x[0].pdfFwd = pdfLightOrigin(scene, x[0]);
        x[0].beta = Color(x[0].pdfFwd > 0.0f ? 1.0f / x[0].pdfFwd : 0.0f);
        x[0].pdfRev = 0.0f;
        x[0].misSum = 0.0;
    }
    PathVertex z = c.lens;
    // The light side's density of z: y_m's step, as the light subpath would have taken it.
    z.pdfFwd = m == 0 ? pdfLightToward(scene, x[0], z)
                      : pdfScatter(scene, &x[size_t(m) - 1], x[size_t(m)], z, Transport::Importance);
    z.pdfRev = scene.camera.pdfPoint();
    x.push_back(z);
    // The camera side's densities: of z itself, of y_m from z, and of y_{m-1}, which lightSubpath
    // took from the walk's own next vertex, now from z.
    ReversePdfs rev;
    rev.lightEnd = z.pdfRev;
    rev.lightPrev = pdfScatter(scene, nullptr, z, x[size_t(m)], Transport::Radiance);
    x[size_t(m)].pdfRev = rev.lightPrev;
    if (m >= 1) x[size_t(m) - 1].pdfRev = pdfScatter(scene, &z, x[size_t(m)], x[size_t(m) - 1], Transport::Radiance);
    updateMisSum(x, size_t(m) + 1, h);
    const int s = m + 2;
    return recursive ? misWeightRecursive(x.data(), s, nullptr, 0, rev, h)
                     : misWeightFull(x.data(), s, nullptr, 0, rev, h);
}

void lensTechniques(const Scene& scene, const Subpath& light, Rng& rng, const BptOptions& opt, const SplatTarget& splat,
                    TechniqueRecorder* recorder) {
    if (!thinLens(scene.camera)) return;  // t = 0 needs a camera whose points rays can hit
    static const Subpath noCamera;        // t = 0: every vertex is the light subpath's
    const int maxDepth = scene.settings.maxDepth;
    for (int m = 0; m < static_cast<int>(light.size()) && m <= maxDepth; ++m) {
        const LensConnection c = connectLens(scene, light.data(), m, rng);
        if (!c.valid) continue;
        if (opt.techniqueFilter && !opt.techniqueFilter(light, noCamera, m + 2, 0)) continue;
        const float w = lensMisWeight(scene, light, m, c, opt.heuristic, opt.recursive);
        splat.add(c.raster, c.value * w);
        if (recorder) recorder->add(m + 2, 0, c.raster, c.value * splat.scale, c.value * (w * splat.scale));
    }
}

namespace {
[[maybe_unused]] const bool registered = Registry<ExtraTechnique>::add("t = 0 through a thin lens", lensTechniques);
}  // namespace

}  // namespace ps
