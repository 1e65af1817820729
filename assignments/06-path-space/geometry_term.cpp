// Lesson 6 — the geometry term between two path vertices. Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

float geometryTerm(const PathVertex& a, const PathVertex& b) {
    // TODO(06) G(a, b) without visibility (Eq. 6.4, 6.5; geometryTerm in paths.h). Pitfalls: no cosine at a point
    //          light; an infinite end has no cosine and no 1/d^2; both infinite or d = 0 give 0.
    (void)a; (void)b;
    return PS_TODO("lesson 06: geometryTerm", 0.0f);
}

}  // namespace ps
