// Lesson 5 — the pen-and-paper exercise. Interface: lessons/05-light-tracing/exercises.h.
// Equation numbers refer to lessons/05-light-tracing/README.md ("Exercise (pen and paper)").
#include "05-light-tracing/exercises.h"
#include "todo.h"

namespace ps {

double refractedRadianceScale(double etaFrom, double etaTo) {
    // TODO(05) Eq. 5.E1: from Snell's law, relate cos(theta) d(omega) on both sides, then use that
    //          the refracted flux (without Fresnel) is the incident flux.
    (void)etaFrom; (void)etaTo;
    return PS_TODO("lesson 05: refractedRadianceScale (exercise)", 0.0);
}

}  // namespace ps
