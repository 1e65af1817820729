// Lesson 6, graded: delta vertices are flags (Eq. 6.11, 6.12). Paths through the room's mirror
// and from its point light: the techniques that cannot sample them give p = 0 exactly, those
// that can give the finite value computed here by hand (the mirror's delta contributes its
// lobe probability 1, never a huge number), and a path no technique can sample (point light ->
// mirror -> pinhole) gives 0 under every technique. Never NaN or Inf.
#include "lesson06.h"

using namespace lesson06;

namespace {

DVec3 d3(const Vec3& v) { return DVec3(v); }
// A solid-angle pdf at a to an area pdf at b with normal nb (by hand, Eq. 6.6).
double toArea(double pdfW, const DVec3& a, const DVec3& b, const DVec3& nb) {
    const DVec3 d = b - a;
    return pdfW * std::abs(glm::dot(nb, glm::normalize(d))) / glm::dot(d, d);
}
double cosBetween(const DVec3& n, const DVec3& a, const DVec3& b) {
    return std::abs(glm::dot(n, glm::normalize(b - a)));
}

// The mirror point between x0 and the floor point pf (the mirror is the plane x = -2).
DVec3 mirrorPoint(const DVec3& p0, const DVec3& pf) {
    const DVec3 img(-4.0 - pf.x, pf.y, pf.z);
    return p0 + ((-2.0 - p0.x) / (img.x - p0.x)) * (img - p0);
}

void checkTechniques(const ps::Path& x, const std::vector<double>& expected, const std::string& what) {
    const ps::Scene& scene = room();
    for (size_t s = 0; s < expected.size(); ++s) {
        const double got = ps::pdfTechnique(scene, x, int(s));
        INFO(what << ": technique (s, t) = (" << s << ", " << x.size() - s << "), path " << describe(x));
        CHECK_MESSAGE(std::isfinite(got), "expected a finite pdf, got " << got);
        if (expected[s] == 0.0)
            CHECK_MESSAGE(
                got == 0.0,
                "this technique cannot sample the path (a delta vertex at an end of the joining edge, s = 0 with a "
                "point light, or t = 0): expected p = 0 exactly, got "
                    << num(got));
        else
            CHECK_MESSAGE(close(got, expected[s], 1e-3), "expected p = " << num(expected[s])
                                                                         << " (the mirror's delta counts as its lobe "
                                                                            "probability 1), got "
                                                                         << num(got));
    }
}

}  // namespace

TEST_CASE(
    "path space: through a mirror and from a point light, only the techniques that can sample a path have p > 0, and p is finite (Eq. 6.11, 6.12) [3 pts]") {
    const ps::Scene& scene = room();
    const ps::PathVertex x0 = areaLightPoint(scene, Vec3(0.0f, 2.0f, 0.0f)), pl = pointLightVertex(scene),
                         cam = pinhole(scene);
    const ps::PathVertex floor = surface(scene, Vec3(0.3f, 0.0f, 0.4f), Vec3(0, 1, 0), "floor");
    const DVec3 p0 = d3(x0.sp.p), pf = d3(floor.sp.p), pc = d3(cam.sp.p), pp = d3(pl.sp.p);
    const DVec3 up(0, 1, 0), down(0, -1, 0), nx(1, 0, 0), fwd = d3(scene.camera.forward());
    const double P = scene.lightSelectionProb(x0.sp.light), Pp = scene.lightSelectionProb(pl.sp.light);
    const double ty = std::tan(30.0 * kPi / 180.0), A = 4.0 * ty * ty;
    auto cameraPdfW = [&](const DVec3& p) {
        const double c = cosBetween(fwd, pc, p);
        return 1.0 / (A * c * c * c);
    };
    {
        // area light -> mirror -> floor -> pinhole: s = 0 (the camera's ray reflects into the
        // light) and s = 3 (light tracing) sample it; s = 1, 2 would join at the mirror.
        const DVec3 pm = mirrorPoint(p0, pf);
        const ps::PathVertex m = surface(scene, Vec3(pm), Vec3(1, 0, 0), "mirror");
        const ps::Path x = {x0, m, floor, cam};
        const double s0 = toArea(cameraPdfW(pf), pc, pf, up) * toArea(cosBetween(up, pf, pm) / kPi, pf, pm, nx) *
                          toArea(1.0, pm, p0, down);
        const double s3 =
            P * 1.0 * toArea(cosBetween(down, p0, pm) / kPi, p0, pm, nx) * toArea(1.0, pm, pf, up);  // light area 1
        checkTechniques(x, {s0, 0.0, 0.0, s3, 0.0}, "area light -> mirror -> floor -> pinhole");
    }
    {
        // point light -> mirror -> floor -> pinhole: only light tracing (s = 3).
        const DVec3 pm = mirrorPoint(pp, pf);
        const ps::PathVertex m = surface(scene, Vec3(pm), Vec3(1, 0, 0), "mirror");
        const ps::Path x = {pl, m, floor, cam};
        const double s3 = Pp * toArea(1.0 / (4.0 * kPi), pp, pm, nx) * toArea(1.0, pm, pf, up);
        checkTechniques(x, {0.0, 0.0, 0.0, s3, 0.0}, "point light -> mirror -> floor -> pinhole");
    }
    {
        // point light -> floor -> pinhole: every technique but s = 0 and t = 0.
        const ps::Path x = {pl, floor, cam};
        const double s1 = Pp * toArea(cameraPdfW(pf), pc, pf, up);
        const double s2 = Pp * toArea(1.0 / (4.0 * kPi), pp, pf, up);
        checkTechniques(x, {0.0, s1, s2, 0.0}, "point light -> floor -> pinhole");
    }
    {
        // point light -> mirror -> pinhole (L S E): no technique samples it (Eq. 6.12).
        const DVec3 img(-4.0 - pc.x, pc.y, pc.z);
        const DVec3 pm = pp + ((-2.0 - pp.x) / (img.x - pp.x)) * (img - pp);
        const ps::PathVertex m = surface(scene, Vec3(pm), Vec3(1, 0, 0), "mirror");
        checkTechniques({pl, m, cam}, {0.0, 0.0, 0.0, 0.0},
                        "point light -> mirror -> pinhole (no technique can sample it)");
    }
}
