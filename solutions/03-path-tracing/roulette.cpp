// Lesson 3 — Russian roulette. Interface: lessons/03-path-tracing/pathtracer.h.
// Equation numbers refer to lessons/03-path-tracing/README.md.
#include <algorithm>
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

float survivalProbability(const Color& beta, int bounces) {
    //! TODO(03) Eq. 3.5: 1 while bounces < kRouletteStartBounces; after that the largest
    //!          component of beta, clamped to [kRouletteMinSurvival, 1].
    //! STUB (void)beta; (void)bounces;
    //! STUB return PS_TODO("lesson 03: survivalProbability", 1.0f);
    //! BEGIN
    if (bounces < kRouletteStartBounces) return 1.0f;
    return std::clamp(maxComponent(beta), kRouletteMinSurvival, 1.0f);
    //! END
}

}  // namespace ps
