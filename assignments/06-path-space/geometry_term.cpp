// Lesson 6 — the geometry term between two path vertices. Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

float geometryTerm(const PathVertex& a, const PathVertex& b) {
    // TODO(06) Eq. 6.4, 6.5: G(a, b) = |cos theta_a| |cos theta_b| / d^2, no visibility.
    //          Pitfalls: no cosine at a point light (the pinhole has one, to camera.forward()); an
    //          infinite end has no cosine and no 1/d^2 (sp.n is the direction towards it); both
    //          infinite or d = 0: 0.
    (void)a; (void)b;
    return PS_TODO("lesson 06: geometryTerm", 0.0f);
}

}  // namespace ps
