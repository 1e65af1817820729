// Values as text for failure messages: "(x, y, z)" with enough digits to see the difference.
#pragma once
#include <sstream>
#include <string>
#include "vecmath.h"

namespace ps::fmt {

inline std::string num(double x, int digits = 7) {
    std::ostringstream s;
    s.precision(digits);
    s << x;
    return s.str();
}
inline std::string str(const Vec2& v) { return "(" + num(v.x, 9) + ", " + num(v.y, 9) + ")"; }
inline std::string str(const Vec3& v) { return "(" + num(v.x, 9) + ", " + num(v.y, 9) + ", " + num(v.z, 9) + ")"; }
inline std::string str(const glm::dvec3& v) {
    return "(" + num(v.x, 12) + ", " + num(v.y, 12) + ", " + num(v.z, 12) + ")";
}

}  // namespace ps::fmt
