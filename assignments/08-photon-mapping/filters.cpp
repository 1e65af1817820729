// Lesson 8 — the filters of the density estimate. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <cmath>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

float filterKernel(Filter f, float d2, float r2, float coneK) {
    // TODO(08) K(d) of Eq. 8.7-8.10 for the given filter, each normalised over the disc of radius r (photonmap.h); 0
    //          outside it. Pitfall: d2 and r2 are squared distances, while the cone is linear in d.
    (void)f; (void)d2; (void)r2; (void)coneK;
    return PS_TODO("lesson 08: filterKernel", 0.0f);
}

}  // namespace ps
