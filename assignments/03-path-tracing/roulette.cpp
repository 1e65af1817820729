// Lesson 3 — Russian roulette. Interface: lessons/03-path-tracing/pathtracer.h.
// Equation numbers refer to lessons/03-path-tracing/README.md.
#include <algorithm>
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

float survivalProbability(const Color& beta, int bounces) {
    // TODO(03) The survival probability q of Eq. 3.5 after `bounces` bounces (its constants: README, under Eq. 3.5).
    (void)beta; (void)bounces;
    return PS_TODO("lesson 03: survivalProbability", 1.0f);
}

}  // namespace ps
