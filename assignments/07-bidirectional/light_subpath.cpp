// Lesson 7 — the light subpath y_0 .. y_{s-1} (Eq. 7.1, 7.3). Interface:
// lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void lightSubpath(const Scene& scene, Rng& rng, int maxDepth, Heuristic h, Subpath& path) {
    // TODO(07) Eq. 7.1, 7.3: lesson 5's light walk (startLightPath, sampleAdjointBSDF, Russian
    //          roulette) storing y_0 .. y_{s-1}, at most maxDepth + 1 vertices: y_0 = start.y0 with
    //          onLight, pointLight, infinite (sp.n towards the background, as lesson 6's
    //          backgroundVertex), pdfFwd = pdfLightOrigin, beta = 1 / pdfFwd; each hit a
    //          surfaceVertex with beta (from start.beta on), pdfFwd (pdfLightToward for y_1, else
    //          pdfScatter Importance); then y_{i-2}.pdfRev (pdfScatter Radiance) and
    //          updateMisSum(path, i, h) for every i.
    //          Pitfalls: pdfFwd from the vertices' positions (the same function the weights use),
    //          not the sample's pdf; a reference into `path` dies at push_back.
    (void)scene; (void)rng; (void)maxDepth; (void)h;
    path.clear();
    (void)PS_TODO("lesson 07: lightSubpath", 0);
}

}  // namespace ps
