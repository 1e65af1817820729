// Lesson 11's pen-and-paper exercise (lessons/11-classics/README.md, "Exercise (pen and paper)"):
// derive the answer on paper, then type the closed form into solutions/11-classics/exercises.cpp
// (reference) or assignments/11-classics/exercises.cpp (yours).
#pragma once

namespace ps {

// The form factor from a differential area dA at a point x to a disk of radius R, parallel to dA,
// facing it, centred on x's normal at the distance h (both > 0): the inner integral of Eq. 11.22,
// the integral over the disk of cos(theta_x) cos(theta_y) / (pi r^2) (Eq. 11.E1).
double diskFormFactor(double R, double h);

}  // namespace ps
