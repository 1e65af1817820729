// Lesson 4's pen-and-paper exercise (lessons/04-measurement/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/04-measurement/exercises.cpp (reference) or assignments/04-measurement/exercises.cpp (yours).
#pragma once

namespace ps {

// The emitted importance W_e of a pinhole camera whose whole image is a rectangle of area
// imageArea on the plane at distance focalDistance in front of the pinhole (not 1 as in the
// framework), along a direction at angle theta to the camera's axis that passes through the
// image (cosTheta > 0), normalised like Eq. 4.5 (Eq. 4.E1).
double pinholeImportance(double imageArea, double focalDistance, double cosTheta);

}  // namespace ps
