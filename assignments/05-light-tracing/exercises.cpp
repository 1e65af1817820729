// Lesson 5 — the pen-and-paper exercise. Interface: lessons/05-light-tracing/exercises.h.
// Equation numbers refer to lessons/05-light-tracing/README.md ("Exercise (pen and paper)").
#include "05-light-tracing/exercises.h"
#include "todo.h"

namespace ps {

double refractedRadianceScale(double etaFrom, double etaTo) {
    // TODO(05) L_t / L_i of Eq. 5.E1 (without Fresnel), solved on paper from Snell's law and the flux that crosses.
    (void)etaFrom; (void)etaTo;
    return PS_TODO("lesson 05: refractedRadianceScale (exercise)", 0.0);
}

}  // namespace ps
