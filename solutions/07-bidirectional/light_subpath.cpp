// Lesson 7 — the light subpath y_0 .. y_{s-1} (Eq. 7.1, 7.3): lesson 5's walk, storing its
// vertices. Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to
// lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void lightSubpath(const Scene& scene, Rng& rng, int maxDepth, Heuristic h, Subpath& path) {
    //! TODO(07) The light subpath (Eq. 7.1, 7.1a, 7.3), as lightSubpath in bpt.h states it, y_0 with the flags of lesson
    //!          6's vertices and its origin density (0: no subpath). Pitfalls (README 6): pdfFwd evaluated from the
    //!          positions, not the sample's pdf; a reference into `path` dies at push_back.
    //! STUB (void)scene; (void)rng; (void)maxDepth; (void)h;
    //! STUB path.clear();
    //! STUB (void)PS_TODO("lesson 07: lightSubpath", 0);
    //! BEGIN
    path.clear();
    WalkOptions opt(maxDepth);
    opt.continuation = [&scene](const WalkVertex& v, Rng& r) { return subpathContinuation(scene, v, r); };
    lightWalk(scene, rng, opt, [&](const WalkVertex& w, const LightPathStart& start) {
        if (w.bounces == 0) {
            const Light& light = scene.lights[size_t(start.light)];
            PathVertex y0;
            y0.sp = start.y0;
            y0.onLight = true;
            y0.pointLight = light.isDelta();
            y0.infinite = light.isInfinite();
            if (y0.infinite) y0.sp.n = -start.ray.d;  // towards the background (lesson 6's convention)
            y0.pdfFwd = pdfLightOrigin(scene, y0);
            if (!(y0.pdfFwd > 0.0f)) return false;
            y0.beta = Color(1.0f / y0.pdfFwd);
            path.push_back(y0);
            updateMisSum(path, 0, h);
            return true;
        }
        PathVertex v = surfaceVertex(scene, w.sp);
        v.beta = w.beta;
        const PathVertex& prev = path.back();
        if (w.bounces == 1) v.pdfFwd = pdfLightToward(scene, prev, v);
        else v.pdfFwd = pdfScatter(scene, &path[path.size() - 2], prev, v, Transport::Importance);
        path.push_back(v);
        const size_t i = path.size() - 1;
        if (i >= 2) path[i - 2].pdfRev = pdfScatter(scene, &path[i], path[i - 1], path[i - 2], Transport::Radiance);
        updateMisSum(path, i, h);
        return true;
    });
    //! END
}

}  // namespace ps
