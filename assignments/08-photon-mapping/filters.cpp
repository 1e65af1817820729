// Lesson 8 — the filters of the density estimate. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <cmath>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

float filterKernel(Filter f, float d2, float r2, float coneK) {
    // TODO(08) Eq. 8.7-8.10, each normalised to integrate to 1 over the disc of radius r
    //          (0 outside it, d2 > r2):
    //          box       K = 1 / (pi r^2)                                               (8.7)
    //          cone      K = (1 - d / (k r)) / ((1 - 2 / (3k)) pi r^2), k = coneK       (8.8, 8.9)
    //          Gaussian  K = alpha [1 - (1 - e^(-beta d^2/r^2)) / (1 - e^(-beta))] / r^2,
    //                    alpha = kGaussAlpha, beta = kGaussBeta                          (8.10)
    (void)f; (void)d2; (void)r2; (void)coneK;
    return PS_TODO("lesson 08: filterKernel", 0.0f);
}

}  // namespace ps
