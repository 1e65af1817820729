// Lesson 13's pen-and-paper exercise (lessons/13-vcm/README.md, "Exercise (pen and paper)"):
// derive the answer on paper, then type the closed form into solutions/13-vcm/exercises.cpp
// (reference) or assignments/13-vcm/exercises.cpp (yours).
#pragma once

namespace ps {

// A path x_0 x_1 x_2 (x_0 on an area light, x_1 diffuse, x_2 the pinhole) sampled by the three
// connections s = 0, 1, 2 with densities pdf[0..2] and by the merge at x_1, whose light subpath
// reaches x_1 with area density pdfLight1. With eta_i = eta1 i^(alpha - 1) (Eq. 13.5, 13.12) and
// the heuristic's exponent b: the iteration i (a real number) at which the merge's weight is 1/2
// (Eq. 13.E1); 1 if it is at most 1/2 already at i = 1; +infinity if it never falls to 1/2.
double halfMergeIteration(const double pdf[3], double pdfLight1, double eta1, double alpha, double b);

}  // namespace ps
