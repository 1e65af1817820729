// Lesson 6 — the geometry term between two path vertices. Interface:
// lessons/06-path-space/paths.h. Equation numbers refer to lessons/06-path-space/README.md.
#include "06-path-space/paths.h"
#include "todo.h"

namespace ps {

float geometryTerm(const PathVertex& a, const PathVertex& b) {
    //! TODO(06) G(a, b) without visibility (Eq. 6.4, 6.5; geometryTerm in paths.h). Pitfalls: no cosine at a point
    //!          light; an infinite end has no cosine and no 1/d^2; both infinite or d = 0 give 0.
    //! STUB (void)a; (void)b;
    //! STUB return PS_TODO("lesson 06: geometryTerm", 0.0f);
    //! BEGIN
    if (a.infinite && b.infinite) return 0.0f;
    if (a.infinite || b.infinite) {
        const PathVertex& f = a.infinite ? b : a;
        const Vec3& w = a.infinite ? a.sp.n : b.sp.n;
        return f.pointLight ? 1.0f : std::abs(glm::dot(f.sp.n, w));
    }
    const Vec3 d = b.p() - a.p();
    const float d2 = glm::dot(d, d);
    if (!(d2 > 0.0f)) return 0.0f;
    const Vec3 w = d / std::sqrt(d2);
    const float cosA = a.pointLight ? 1.0f : std::abs(glm::dot(a.sp.n, w));
    const float cosB = b.pointLight ? 1.0f : std::abs(glm::dot(b.sp.n, w));
    return cosA * cosB / d2;
    //! END
}

}  // namespace ps
