// Lesson 6's pen-and-paper exercise (lessons/06-path-space/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/06-path-space/exercises.cpp (reference) or assignments/06-path-space/exercises.cpp (yours).
#pragma once
#include "vecmath.h"

namespace ps {

// The area-measure pdf p_{2,1} of the first two vertices x0 x1 of a path of length k = 2
// (x0 on the scene's only light, a Lambertian quad of area lightArea, x1 on a surface, x2 the
// pinhole) sampled by the light tracer: x0 uniform on the light, the direction cosine-weighted
// about n0 (Eq. 6.E1). n0 and n1 are unit normals; x1 is in front of the light.
double lightTracerPdfK2(double lightArea, const Vec3& x0, const Vec3& n0, const Vec3& x1, const Vec3& n1);

}  // namespace ps
