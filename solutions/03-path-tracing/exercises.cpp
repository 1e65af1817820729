// Lesson 3 — the pen-and-paper exercise. Interface: lessons/03-path-tracing/exercises.h.
// Equation numbers refer to lessons/03-path-tracing/README.md ("Exercise (pen and paper)").
#include <cmath>
#include "03-path-tracing/exercises.h"
#include "todo.h"

namespace ps {

int furnaceDepthForBias(double albedo, double eps) {
    //! TODO(03) D_min(a, eps) of Eq. 3.E1: the smallest integer depth whose relative bias in the furnace of Eq. 3.8 is
    //!          at most eps (a = 0: 0).
    //! STUB (void)albedo; (void)eps;
    //! STUB return PS_TODO("lesson 03: furnaceDepthForBias (exercise)", 0);
    //! BEGIN
    if (albedo <= 0.0) return 0;
    const double d = std::ceil(std::log(eps) / std::log(albedo)) - 1.0;  // a^(D+1) <= eps
    return d < 0.0 ? 0 : int(d);
    //! END
}

}  // namespace ps
