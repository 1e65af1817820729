// Lesson 13 — the merging radius of each iteration and the factor eta that makes a merge's density
// comparable with a connection's. Interface: lessons/13-vcm/vcm.h. Equation numbers refer to
// lessons/13-vcm/README.md.
#include <cmath>
#include "13-vcm/vcm.h"
#include "todo.h"

namespace ps {

double vcmRadius(double r1, int iteration, double alpha) {
    // TODO(13) r_i of Eq. 13.12 (vcm.h). Pitfall: the schedule shrinks r, not r^2 as lesson 8's Eq. 8.13;
    //          alpha = 1 keeps the radius.
    (void)iteration; (void)alpha;
    return PS_TODO("lesson 13: vcmRadius", r1);
}

double mergeFactor(double radius, int lightPaths) {
    // TODO(13) eta of Eq. 13.5 (vcm.h). Pitfall (README 6): merging's sample count is not 1.
    (void)radius; (void)lightPaths;
    return PS_TODO("lesson 13: mergeFactor", 0.0);
}

}  // namespace ps
