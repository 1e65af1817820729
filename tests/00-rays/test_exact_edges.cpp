// Lesson 0, graded: an edge function that comes out exactly 0 in float must be recomputed in
// double (Eq. 0.4), or a ray that passes just beside an edge counts as ON the edge and hits the
// triangles on BOTH sides. Found missing by scripts/mutants.sh (the watertightness tests only
// look for holes, and the shortcut makes none: it makes double hits).
// The case, with the ray from the origin along +z (so the shear is the identity): B and C are
// chosen so that Cx By = -(1 + 2^-12)^2 = -(1 + 2^-11 + 2^-24) rounds in float to exactly
// Cy Bx = -(1 + 2^-11): U is 0 in float, -2^-24 exactly. The ray passes 2e-8 beside the edge BC,
// on the side of the triangle (A2, C, B): that one must be hit, (A1, B, C) must be missed.
#include <doctest/doctest.h>
#include <cmath>
#include "lesson00.h"

using namespace lesson00;

TEST_CASE(
    "rays: edge functions that round to 0 in float are recomputed exactly: a ray 2e-8 beside an edge hits one side only (Eq. 0.4) [1 pt]") {
    const float e11 = std::ldexp(1.0f, -11), e12 = std::ldexp(1.0f, -12);
    const Vec3 B(1.0f + e11, 1.0f + e12, 1.0f), C(-(1.0f + e12), -1.0f, 1.0f);
    const Triangle outside{Vec3(-1.0f, 1.0f, 1.0f), B, C};  // the ray passes just outside its edge BC
    const Triangle inside{Vec3(1.0f, -1.0f, 1.0f), C, B};   // ... and just inside this one's
    const Ray ray(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f));
    const Hit hOut = intersect(ray, outside), hIn = intersect(ray, inside);
    CHECK_MESSAGE((hIn.hit && std::abs(hIn.t - 1.0f) <= 1e-6f), "ray " << str(ray) << " against " << str(inside)
                                                                       << ": expected a hit at t = 1 (the ray passes "
                                                                       << "2e-8 inside the edge), got " << str(hIn));
    CHECK_MESSAGE(!hOut.hit, "ray " << str(ray) << " against " << str(outside) << ": expected no hit (the ray passes "
                                    << "2e-8 outside the edge BC, whose edge function U rounds to 0 in float but is "
                                    << "-2^-24 exactly), got " << str(hOut)
                                    << ": an edge function that is exactly 0 must be recomputed in double (Eq. 0.4)");
}
