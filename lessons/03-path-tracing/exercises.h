// Lesson 3's pen-and-paper exercise (lessons/03-path-tracing/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/03-path-tracing/exercises.cpp (reference) or assignments/03-path-tracing/exercises.cpp (yours).
#pragma once

namespace ps {

// The smallest maximum depth D (bounces) at which a path tracer's expected radiance L_D in the
// closed furnace of albedo a (Eq. 3.8) is within a relative bias eps of the untruncated L_inf:
// (L_inf - L_D) / L_inf <= eps (Eq. 3.E1). 0 <= albedo < 1, 0 < eps < 1.
int furnaceDepthForBias(double albedo, double eps);

}  // namespace ps
