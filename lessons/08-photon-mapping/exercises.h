// Lesson 8's pen-and-paper exercise (lessons/08-photon-mapping/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/08-photon-mapping/exercises.cpp (reference) or assignments/08-photon-mapping/exercises.cpp (yours).
#pragma once

namespace ps {

// The bias E[estimate] - E(x0) of the box-filter estimate of irradiance (Eq. 8.7 with photons of
// density E / DeltaPhi, every photon within radius r of x0 counted) at a point x0 of a plane
// whose irradiance is E(x0 + (u, v)) = e0 + gx u + gy v + a u^2 + b v^2 + c u v (Eq. 8.E1).
double boxFilterBias(double gx, double gy, double a, double b, double c, double r);

}  // namespace ps
