// Lesson 6 — the area-measure pdf p_{s,t}(x) of a path under technique (s, t). Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

double pdfTechnique(const Scene& scene, const Path& x, int s) {
    // Given: a technique of this path at all (s from 0 to k + 1, k >= 1). Not the student's: a
    // missing check would read before the path (x[-1]), which no test can observe reliably.
    if (x.size() < 2 || s < 0 || s > int(x.size())) return 0.0;
    // TODO(06) p_{s,t}(x) per unit area (Eq. 6.7-6.10), in double, 0 for what technique s cannot sample (Eq. 6.12), as
    //          pdfTechnique in paths.h states it; x0 and x1 as startLightPath samples them, specular vertices as in
    //          contribution. Pitfalls (README 6): the BSDF's argument order in each subpath; P(l) p_A(x0) counts even
    //          for s = 1; no Russian roulette.
    (void)scene; (void)x; (void)s;
    return PS_TODO("lesson 06: pdfTechnique", 0.0);
}

}  // namespace ps
