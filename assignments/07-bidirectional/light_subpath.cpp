// Lesson 7 — the light subpath y_0 .. y_{s-1} (Eq. 7.1, 7.3): lesson 5's walk, storing its
// vertices. Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to
// lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void lightSubpath(const Scene& scene, Rng& rng, int maxDepth, Heuristic h, Subpath& path) {
    // TODO(07) Eq. 7.1, 7.3: clear path, then lesson 5's lightWalk with a visitor that stores
    //          every vertex it is shown, at most maxDepth + 1: y_0 from the walk's start (onLight,
    //          pointLight, infinite with sp.n towards the background, as lesson 6's
    //          backgroundVertex), pdfFwd = pdfLightOrigin (0: end the walk), beta = 1 / pdfFwd;
    //          each later vertex a surfaceVertex with the walk's beta and pdfFwd (pdfLightToward
    //          for y_1, else pdfScatter Importance); then y_{i-2}.pdfRev (pdfScatter Radiance)
    //          and updateMisSum(path, i, h) for every i.
    //          Pitfalls: pdfFwd from the vertices' positions (the same function the weights use),
    //          not the sample's pdf; a reference into `path` dies at push_back.
    (void)scene; (void)rng; (void)maxDepth; (void)h;
    path.clear();
    (void)PS_TODO("lesson 07: lightSubpath", 0);
}

}  // namespace ps
