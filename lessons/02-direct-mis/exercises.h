// Lesson 2's pen-and-paper exercise (lessons/02-direct-mis/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/02-direct-mis/exercises.cpp (reference) or assignments/02-direct-mis/exercises.cpp (yours).
#pragma once

namespace ps {

// The solid angle (steradians) that a sphere of the given radius subtends at a point at the
// given distance from its centre, distance > radius > 0 (Eq. 2.E1).
double sphereSolidAngle(double radius, double distance);

}  // namespace ps
