// Lesson 1's pen-and-paper exercise (lessons/01-monte-carlo/README.md, "Exercise (pen and
// paper)"): derive the answer on paper, then type the closed form into
// solutions/01-monte-carlo/exercises.cpp (reference) or assignments/01-monte-carlo/exercises.cpp (yours).
#pragma once

namespace ps {

// The constant C(n) of the Phong lobe used as a BRDF, f = C(n) cos^n(alpha), that makes it
// reflect all the light at normal incidence (mirror direction = normal, so alpha = theta): the
// integral of f cos(theta) over the hemisphere is 1 (Eq. 1.E1). Exponent n >= 0.
double phongBRDFNormalization(double n);

}  // namespace ps
