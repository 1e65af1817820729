// Lesson 6 — the geometry term between two path vertices. Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

float geometryTerm(const PathVertex& a, const PathVertex& b) {
    // TODO(06) G(a, b) = |cos theta_a| |cos theta_b| / d^2 without visibility (Eq. 6.4, 6.5):
    //          1. Both infinite: 0. One infinite (say a): w = a.sp.n (the direction from b
    //             towards the background); G = |cos theta_b| = |dot(b.sp.n, w)|, no 1/d^2
    //             (and no cosine at all if b is a point light).
    //          2. Otherwise d = b.p() - a.p(), d2 = dot(d, d) (0 if d2 is 0), w = d / sqrt(d2);
    //             cos theta_a = |dot(a.sp.n, w)|, cos theta_b = |dot(b.sp.n, w)|, but 1 at a
    //             point light (no surface). The pinhole has its cosine: its sp.n is
    //             camera.forward(). G = cos theta_a cos theta_b / d2.
    (void)a; (void)b;
    return PS_TODO("lesson 06: geometryTerm", 0.0f);
}

}  // namespace ps
