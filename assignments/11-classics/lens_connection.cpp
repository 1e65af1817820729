// Lesson 11 — bidirectional path tracing's technique t = 0: a light subpath that hits the lens.
// Interface: lessons/11-classics/thinlens.h. Equation numbers refer to lessons/11-classics/README.md.
#include "11-classics/thinlens.h"
#include "todo.h"

namespace ps {

LensConnection connectLens(const Scene& scene, const PathVertex* y, int m, Rng& rng) {
    // TODO(11) The technique t = 0 at y_m (Eq. 11.16, 11.17), as connectLens and LensConnection in thinlens.h state
    //          it, with the numbers drawn in the order stated there (the tests replay them). Pitfalls (README 6): no
    //          cosine or 1 / d^2 in the value; only what lies between y_m and the lens blocks it; a specular y_m is
    //          fine.
    (void)scene; (void)y; (void)m; (void)rng;
    return PS_TODO("lesson 11: connectLens", LensConnection());
}

}  // namespace ps
