// Lesson 6, graded: the geometry term (Eq. 6.4, 6.5) and the solid-angle -> area conversion
// (Eq. 6.6) against values computed here by hand, including a point light, the pinhole and an
// infinite (background) vertex.
#include "lesson06.h"

using namespace lesson06;

namespace {

ps::PathVertex at(const Vec3& p, const Vec3& n) {
    ps::PathVertex v;
    v.sp.p = p;
    v.sp.n = glm::normalize(n);
    return v;
}

}  // namespace

TEST_CASE(
    "path space: the geometry term G = |cos a| |cos b| / d^2, with point lights, the pinhole and the background (Eq. 6.4, 6.5) [2 pts]") {
    // a = (0,0,0) facing +y, b = (3,4,0) facing -x: d^2 = 25, cos a = 4/5, cos b = 3/5.
    const ps::PathVertex a = at(Vec3(0, 0, 0), Vec3(0, 1, 0)), b = at(Vec3(3, 4, 0), Vec3(-1, 0, 0));
    struct Case {
        std::string what;
        ps::PathVertex u, v;
        double expected;
    };
    ps::PathVertex pl = at(Vec3(3, 4, 0), Vec3(0, 0, 1));  // its normal must be ignored
    pl.pointLight = true;
    ps::PathVertex cam = at(Vec3(3, 4, 0), Vec3(0, -1, 0));  // the pinhole, forward -y
    cam.pinhole = true;
    ps::PathVertex back = at(Vec3(100, 100, 100), glm::normalize(Vec3(1, 2, 2)));  // direction (1,2,2)/3
    back.infinite = true;
    ps::PathVertex backPl = pl;
    backPl.sp.p = Vec3(1, 1, 1);
    const ps::PathVertex tilted = at(Vec3(0, 0, 0), Vec3(1, 1, 0));
    std::vector<Case> cases = {
        {"two surfaces", a, b, (4.0 / 5.0) * (3.0 / 5.0) / 25.0},
        {"two surfaces, reversed", b, a, (4.0 / 5.0) * (3.0 / 5.0) / 25.0},
        {"a surface seen from behind (|cos|)", at(Vec3(0, 0, 0), Vec3(0, -1, 0)), b, (4.0 / 5.0) * (3.0 / 5.0) / 25.0},
        {"a tilted surface to a point light (no cosine at the light)", tilted, pl, (7.0 / 5.0 / std::sqrt(2.0)) / 25.0},
        {"a point light to a tilted surface", pl, tilted, (7.0 / 5.0 / std::sqrt(2.0)) / 25.0},
        {"a surface to the pinhole (cosine to camera.forward())", a, cam, (4.0 / 5.0) * (4.0 / 5.0) / 25.0},
        {"a point light to the pinhole", pl.sp.p == cam.sp.p ? backPl : pl, cam, 0.0},
        {"the background to a surface (no 1/d^2)", back, a, 2.0 / 3.0},
        {"a surface to the background", tilted, back, (3.0 / 3.0) / std::sqrt(2.0)},
        {"the background to a point light", back, backPl, 1.0},
    };
    // point light at (1,1,1) to the pinhole at (3,4,0): d = (2,3,-1), d^2 = 14, cos at the pinhole = 3/sqrt(14).
    cases[6].expected = (3.0 / std::sqrt(14.0)) / 14.0;
    for (const Case& c : cases) {
        const double got = ps::geometryTerm(c.u, c.v);
        CHECK_MESSAGE(close(got, c.expected, 1e-5), c.what << ": a at " << str(c.u.sp.p) << ", b at " << str(c.v.sp.p)
                                                           << ": expected G = " << num(c.expected) << ", got "
                                                           << num(got));
    }
}

TEST_CASE("path space: a solid-angle pdf as an area pdf, pdfW |cos theta_to| / d^2 (Eq. 6.6) [1 pt]") {
    const ps::PathVertex a = at(Vec3(0, 0, 0), Vec3(0, 1, 0)), b = at(Vec3(3, 4, 0), Vec3(-1, 0, 0));
    ps::PathVertex pl = at(Vec3(3, 4, 0), Vec3(0, 0, 1));
    pl.pointLight = true;
    ps::PathVertex back = at(Vec3(3, 4, 0), Vec3(0, 1, 0));
    back.infinite = true;
    ps::PathVertex eye = at(Vec3(3, 4, 0), Vec3(1, 0, 0));  // its normal meaningless: no surface there
    eye.pinhole = true;
    struct Case {
        std::string what;
        ps::PathVertex from, to;
        double pdfW, expected;
    };
    const std::vector<Case> cases = {
        {"to a surface", a, b, 0.7, 0.7 * (3.0 / 5.0) / 25.0},
        {"back, to a surface", b, a, 0.7, 0.7 * (4.0 / 5.0) / 25.0},
        {"to a point (no surface, no cosine)", a, pl, 0.25, 0.25 / 25.0},
        {"to the pinhole (a point too: no cosine)", a, eye, 0.25, 0.25 / 25.0},
        {"to the background (solid angle stays)", a, back, 0.3, 0.3},
    };
    for (const Case& c : cases) {
        const double got = ps::pdfSolidAngleToArea(float(c.pdfW), c.from, c.to);
        CHECK_MESSAGE(close(got, c.expected, 1e-5), c.what << ": from " << str(c.from.sp.p) << " to " << str(c.to.sp.p)
                                                           << ", pdfW " << c.pdfW << ": expected " << num(c.expected)
                                                           << " per unit area, got " << num(got));
    }
}
