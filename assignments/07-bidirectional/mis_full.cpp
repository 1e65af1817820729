// Lesson 7 — MIS weights from the full list of the joined path's technique pdfs (Eq. 7.5-7.7).
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

bool techniqueSamples(const PathVertex* x, int n, int sPrime) {
    // Given: a technique of this path at all (s' from 0 to n). Not the student's: a missing check
    // would read before the path (x[-1]), which no test can observe reliably.
    if (sPrime < 0 || sPrime > n) return false;
    // TODO(07) Whether technique s' can make the joined path (Eq. 7.7, 7.12; techniqueSamples in bpt.h). Pitfall
    //          (README 6): the pinhole and a point light cannot be hit, a camera model's point can.
    (void)x; (void)n; (void)sPrime;
    return PS_TODO("lesson 07: techniqueSamples", false);
}

float misWeightFull(const PathVertex* y, int s, const PathVertex* z, int t, const ReversePdfs& rev, Heuristic h) {
    // TODO(07) w_{s,t} from the full list of the joined path's densities (Eq. 7.5-7.7; misWeightFull in bpt.h).
    //          Pitfalls (README 6): a specular vertex's density is its coefficient, and a 0 stays 0; sum in double; 0
    //          if the sum is 0.
    (void)y; (void)s; (void)z; (void)t; (void)rev; (void)h;
    return PS_TODO("lesson 07: misWeightFull", 0.0f);
}

}  // namespace ps
