// Lesson 8 — the filters of the density estimate. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <cmath>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

float filterKernel(Filter f, float d2, float r2, float coneK) {
    //! TODO(08) K(d) of Eq. 8.7-8.10 for the given filter, each normalised over the disc of radius r (photonmap.h); 0
    //!          outside it. Pitfall: d2 and r2 are squared distances, while the cone is linear in d.
    //! STUB (void)f; (void)d2; (void)r2; (void)coneK;
    //! STUB return PS_TODO("lesson 08: filterKernel", 0.0f);
    //! BEGIN
    if (!(d2 <= r2) || r2 <= 0.0f) return 0.0f;
    switch (f) {
    case Filter::Box: return 1.0f / (kPi * r2);
    case Filter::Cone: {
        const float d = std::sqrt(d2), r = std::sqrt(r2);
        return (1.0f - d / (coneK * r)) / ((1.0f - 2.0f / (3.0f * coneK)) * kPi * r2);
    }
    case Filter::Gaussian:
        return kGaussAlpha * (1.0f - (1.0f - std::exp(-kGaussBeta * d2 / r2)) / (1.0f - std::exp(-kGaussBeta))) / r2;
    }
    return 0.0f;
    //! END
}

}  // namespace ps
