// Lesson 10's pen-and-paper exercise (lessons/10-adrrs/README.md, "Exercise (pen and paper)"):
// derive the answer on paper, then type the closed form into solutions/10-adrrs/exercises.cpp
// (reference) or assignments/10-adrrs/exercises.cpp (yours).
#pragma once

namespace ps {

// The variance of the estimate n / q of a path that would collect exactly 1 (beta L = 1) and goes
// on with n continuations drawn by Eq. 10.4 (E[n] = q), as a function of q > 0 (Eq. 10.E1).
double splitVariance(double q);

}  // namespace ps
