// Lesson 11 — the ambient term of progressive radiosity's display (Eq. 11.29; Cohen, Chen,
// Wallace and Greenberg 1988). Interface: lessons/11-classics/radiosity.h. Equation numbers refer
// to lessons/11-classics/README.md.
#include "11-classics/radiosity.h"
#include "todo.h"

namespace ps {

Color ambientRadiosity(const ElementMesh& mesh, const RadiositySolution& s) {
    // TODO(11) The ambient radiosity of Eq. 11.29 per channel (radiosity.h), sums in double; a channel whose rho_avg
    //          >= 1 gets 0 (no convergent series). Pitfall: the unshot power is reflected again and again, not once.
    (void)mesh; (void)s;
    return PS_TODO("lesson 11: ambientRadiosity", Color(0.0f));
}

}  // namespace ps
