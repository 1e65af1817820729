// Lesson 12's pen-and-paper exercise (lessons/12-path-guiding/README.md, "Exercise (pen and paper)"):
// derive the answer on paper, then type the closed form into solutions/12-path-guiding/exercises.cpp
// (reference) or assignments/12-path-guiding/exercises.cpp (yours).
#pragma once

namespace ps {

// The relative variance Var[X] / E[X]^2 of the irradiance estimate X = L cos(theta) / p(omega) under
// a uniform sky of radiance L, with one direction from the mixture of a perfect guide (uniform over
// the upper hemisphere) taken with probability alpha and cosine-weighted (BSDF) sampling taken with
// probability 1 - alpha, for alpha in [0, 1] (Eq. 12.E1).
double guidedVariance(double alpha);

}  // namespace ps
