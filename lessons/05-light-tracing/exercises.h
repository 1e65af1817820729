// Lesson 5's pen-and-paper exercise (lessons/05-light-tracing/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/05-light-tracing/exercises.cpp (reference) or assignments/05-light-tracing/exercises.cpp (yours).
#pragma once

namespace ps {

// The factor L_t / L_i by which radiance changes when it is refracted from a medium of index
// etaFrom into one of index etaTo, leaving out the Fresnel factor (1 - F) (Eq. 5.E1).
double refractedRadianceScale(double etaFrom, double etaTo);

}  // namespace ps
