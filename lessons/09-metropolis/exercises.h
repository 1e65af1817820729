// Lesson 9's pen-and-paper exercise (lessons/09-metropolis/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/09-metropolis/exercises.cpp (reference) or assignments/09-metropolis/exercises.cpp (yours).
#pragma once

namespace ps {

// The expected number of times per step that a stationary chain on f(x) = (x - 1/2)^2 with local
// mutations of radius r alone (0 < r <= 1/4) crosses x = 1/2, in either direction (Eq. 9.E1).
double crossingRate(double r);

}  // namespace ps
