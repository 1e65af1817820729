// Lesson 7 — the light subpath y_0 .. y_{s-1} (Eq. 7.1, 7.3): lesson 5's walk, storing its
// vertices. Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to
// lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

void lightSubpath(const Scene& scene, Rng& rng, int maxDepth, Heuristic h, Subpath& path) {
    // TODO(07) The light subpath (Eq. 7.1, 7.1a, 7.3), as lightSubpath in bpt.h states it, y_0 with the flags of lesson
    //          6's vertices and its origin density (0: no subpath). Pitfalls (README 6): pdfFwd evaluated from the
    //          positions, not the sample's pdf; a reference into `path` dies at push_back.
    (void)scene; (void)rng; (void)maxDepth; (void)h;
    path.clear();
    (void)PS_TODO("lesson 07: lightSubpath", 0);
}

}  // namespace ps
