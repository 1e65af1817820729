// Lesson 6, graded: the dielectric's delta lobe (refraction, Eq. 6.11) in f and in p_{s,t}, and
// paths that start at the background light. The room (lesson06.h) with a flat glass surface of
// index 1.6 at y = 1.4 over everything (normal up: air above, glass below), so the light
// (y = 2) is above it and the floor and the camera (y = 1) are "inside the glass": the path
// area light -> glass -> floor -> pinhole refracts once, and only s = 0 (the camera subpath
// refracts towards the light: pdfCamera, with the eta^2 Jacobian) and s = 3 (the light subpath
// refracts towards the floor: pdfLight) can sample it. Every expected value is computed here in
// double from scratch: the refraction point by bisection on Snell's law, Fresnel's formula, and
// the Jacobian d sigma_C / d sigma_L of the refraction map by central finite differences of the
// refracted direction (no eta^2 formula of the lesson appears here). Swapping wLight and wCamera
// in deltaLobe changes f (the cosine it divides by) and the camera's pdf (eta^2): both fail.
#include "lesson06.h"

using namespace lesson06;

namespace {

DVec3 d3(const Vec3& v) { return DVec3(v); }
constexpr double kGlassY = 1.4, kEta = 1.6;

const ps::Scene& pool() {
    static const ps::Scene s = ps::parseScene(std::string(roomText()) +
                                                  "material glass dielectric ior 1.6\n"
                                                  "quad -2 1.4 -4  -2 1.4 2  2 1.4 2  2 1.4 -4  material glass\n",
                                              "the room under a glass surface (test_dielectric.cpp)");
    return s;
}
const ps::Scene& openRoom() {
    static const ps::Scene s = ps::parseScene(std::string(roomText()) + "background radiance 0.5 0.6 0.7\n",
                                              "the room under a sky (test_dielectric.cpp)");
    return s;
}

// Unpolarised Fresnel reflectance for light arriving with cosine cosI on the side of index etaI.
double fresnel(double cosI, double etaI, double etaT) {
    const double sinT2 = (etaI / etaT) * (etaI / etaT) * (1.0 - cosI * cosI);
    if (sinT2 >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sinT2);
    const double rs = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
    const double rp = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
    return 0.5 * (rs * rs + rp * rp);
}
// Snell: the direction leaving the horizontal interface for w arriving (pointing away from the
// surface, on the side of index etaFrom); n = (0, 1, 0).
DVec3 refractY(const DVec3& w, double etaFrom, double etaTo) {
    const double c = std::abs(w.y), eta = etaFrom / etaTo;
    const double cosT = std::sqrt(1.0 - eta * eta * (1.0 - c * c));
    const DVec3 horizontal(-w.x, 0.0, -w.z);
    return horizontal * eta + DVec3(0.0, w.y > 0 ? -cosT : cosT, 0.0);
}
// |d sigma(out) / d sigma(in)| of the refraction map at w, by central finite differences.
double refractionJacobian(const DVec3& w, double etaFrom, double etaTo) {
    DVec3 t1 = glm::normalize(glm::cross(w, DVec3(1, 0, 0))), t2 = glm::cross(w, t1);
    const double h = 1e-5;
    auto at = [&](const DVec3& d) { return refractY(glm::normalize(w + d), etaFrom, etaTo); };
    const DVec3 a = (at(h * t1) - at(-h * t1)) / (2.0 * h), b = (at(h * t2) - at(-h * t2)) / (2.0 * h);
    return glm::length(glm::cross(a, b));
}
// The point on y = kGlassY where light from a (above) refracts towards b (below).
DVec3 refractionPoint(const DVec3& a, const DVec3& b) {
    const DVec3 ah(a.x, 0, a.z), bh(b.x, 0, b.z);
    const double D = glm::length(bh - ah), h1 = a.y - kGlassY, h2 = kGlassY - b.y;
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 200; ++i) {
        const double t = 0.5 * (lo + hi), r1 = t * D, r2 = (1.0 - t) * D;
        const double f = r1 / std::sqrt(r1 * r1 + h1 * h1) - kEta * r2 / std::sqrt(r2 * r2 + h2 * h2);
        (f > 0.0 ? hi : lo) = t;
    }
    const DVec3 g = ah + 0.5 * (lo + hi) * (bh - ah);
    return DVec3(g.x, kGlassY, g.z);
}
double cosAt(const DVec3& n, const DVec3& from, const DVec3& to) {
    return std::abs(glm::dot(n, glm::normalize(to - from)));
}
double toArea(double pdfW, const DVec3& a, const DVec3& b, const DVec3& nb) {
    const DVec3 d = b - a;
    return pdfW * cosAt(nb, a, b) / glm::dot(d, d);
}
double G(const DVec3& a, const DVec3& na, const DVec3& b, const DVec3& nb) {
    const DVec3 d = b - a;
    return cosAt(na, a, b) * cosAt(nb, a, b) / glm::dot(d, d);
}
double sensor(const ps::Scene& scene, const DVec3& p) {
    return double(scene.camera.width()) * double(scene.camera.height()) *
           double(scene.camera.We(glm::normalize(Vec3(p) - scene.camera.position())));
}
double cameraPdfW(const ps::Scene& scene, const DVec3& p) {  // fov 60, square: image area 4 tan^2(30)
    const DVec3 pc = d3(scene.camera.position()), fwd = d3(scene.camera.forward());
    const double ty = std::tan(30.0 * kPi / 180.0), c = cosAt(fwd, pc, p);
    return 1.0 / (4.0 * ty * ty * c * c * c);
}

void checkPdf(const ps::Scene& scene, const ps::Path& x, int s, double expected, const std::string& what) {
    const double got = ps::pdfTechnique(scene, x, s);
    INFO(what << ": technique (s, t) = (" << s << ", " << int(x.size()) - s << "), path " << describe(x));
    CHECK_MESSAGE(std::isfinite(got), "expected a finite pdf, got " << got);
    if (expected == 0.0)
        CHECK_MESSAGE(got == 0.0, "this technique cannot sample the path: expected p = 0 exactly, got " << num(got));
    else
        CHECK_MESSAGE(close(got, expected, 2e-3), "expected p = " << num(expected) << ", got " << num(got) << " (ratio "
                                                                  << num(got / expected) << ")");
}

}  // namespace

TEST_CASE(
    "path space: refraction's delta lobe in f and p_{s,t} (eta^2 of the camera subpath), and paths from the background (Eq. 6.5, 6.11, 6.12) [3 pts]") {
    {
        const ps::Scene& scene = pool();
        const int glass = materialIndex(scene, "glass");
        ps::SurfacePoint hit;
        ps::Ray probe(Vec3(1.5f, 1.9f, -1.0f), Vec3(0.0f, -1.0f, 0.0f));
        const bool up = scene.intersect(probe, hit) && hit.material == glass && hit.n.y > 0.5f;
        REQUIRE_MESSAGE(up, "test setup: the glass surface's normal must point up (air above)");
        const ps::PathVertex x0 = areaLightPoint(scene, Vec3(0.2f, 2.0f, 0.1f)), cam = pinhole(scene);
        const DVec3 p0 = d3(x0.sp.p), pf(-0.4, 0.0, 0.9), pc = d3(cam.sp.p);
        const DVec3 pg = refractionPoint(p0, pf);
        const ps::PathVertex g = surface(scene, Vec3(pg), Vec3(0, 1, 0), "glass");
        const ps::PathVertex floor = surface(scene, Vec3(pf), Vec3(0, 1, 0), "floor");
        const ps::Path x = {x0, g, floor, cam};
        const DVec3 n(0, 1, 0), down(0, -1, 0);
        const DVec3 wL = glm::normalize(p0 - pg), wC = glm::normalize(pf - pg);  // at the glass vertex
        const double cosL = std::abs(wL.y), cosC = std::abs(wC.y);
        REQUIRE_MESSAGE(glm::length(refractY(wL, 1.0, kEta) - wC) < 1e-6,
                        "test setup: the glass vertex must refract x0 into the floor point");
        const double FL = fresnel(cosL, 1.0, kEta), FC = fresnel(cosC, kEta, 1.0);
        // f (Eq. 6.3, 6.11): the refraction's coefficient (1 - F) / |cos theta_C|.
        const double fExpected = G(p0, down, pg, n) * ((1.0 - FL) / cosC) * G(pg, n, pf, n) * (0.5 / kPi) *
                                 G(pf, n, pc, d3(scene.camera.forward())) * sensor(scene, pf);
        const ps::DColor f = ps::contribution(scene, x);
        const double ratio = f.r / (4.0 * fExpected);
        CHECK_MESSAGE(close(f.r, 4.0 * fExpected, 2e-3),
                      "path " << describe(x) << ": expected f = " << num(4.0 * fExpected) << " (red), got " << num(f.r)
                              << " (ratio " << num(ratio)
                              << "): the glass vertex contributes deltaLobe(m, n, wLight, wCamera).fs = (1 - F) / |cos "
                                 "theta_C|"
                              << (close(ratio, cosC / cosL, 1e-2)
                                      ? "; you divided by the cosine on the light's side: wLight and wCamera swapped?"
                                      : ""));
        // p_{s,t}: only s = 0 and s = 3 can sample it.
        const double P = scene.lightSelectionProb(x0.sp.light);
        const double jac =
            refractionJacobian(wC, kEta, 1.0);  // d sigma(wL) / d sigma(wC), sampled from the camera side
        const double s0 = toArea(cameraPdfW(scene, pf), pc, pf, n) * toArea(cosAt(n, pf, pg) / kPi, pf, pg, n) *
                          toArea((1.0 - FC) / jac, pg, p0, down);
        const double s3 = P * 1.0 * toArea(cosAt(down, p0, pg) / kPi, p0, pg, n) * toArea(1.0 - FL, pg, pf, n);
        const std::string what = "area light -> glass (refraction, 1 -> 1.6) -> floor -> pinhole";
        checkPdf(scene, x, 0, s0,
                 what +
                     " (the camera subpath refracts: the lobe probability times |d sigma_C / d sigma_L| "
                     "= pdfCamera, the eta^2 Jacobian; pdfLight there is off by about " +
                     num(1.0 / jac) + ")");
        for (int s : {1, 2, 4}) checkPdf(scene, x, s, 0.0, what);
        checkPdf(scene, x, 3, s3, what + " (the light subpath refracts: the lobe probability 1 - F = pdfLight)");
    }
    {
        // Paths from the background (Eq. 6.5): x0 is a direction, its density per solid angle.
        const ps::Scene& scene = openRoom();
        const ps::PathVertex cam = pinhole(scene);
        const DVec3 pf(0.3, 0.0, 0.4), pc = d3(cam.sp.p), n(0, 1, 0);
        const DVec3 w = glm::normalize(DVec3(0.3, 1.0, 0.25));  // from the floor point to the sky
        const ps::PathVertex sky = ps::backgroundVertex(scene, Vec3(w)),
                             floor = surface(scene, Vec3(pf), Vec3(0, 1, 0), "floor");
        const ps::Path x = {sky, floor, cam};
        const double P = scene.lightSelectionProb(scene.background), R = scene.radius;
        const double fExpected = 0.5 * w.y * (0.5 / kPi) * G(pf, n, pc, d3(scene.camera.forward())) * sensor(scene, pf);
        const ps::DColor f = ps::contribution(scene, x);
        CHECK_MESSAGE(close(f.r, fExpected, 2e-3),
                      "path " << describe(x) << ": expected f = " << num(fExpected)
                              << " (red: L_bg |cos theta_floor| f_s G(floor, pinhole) W_e, no 1/d^2 "
                                 "towards infinity, Eq. 6.5), got "
                              << num(f.r));
        const std::string what = "background -> floor -> pinhole";
        const double camA = toArea(cameraPdfW(scene, pf), pc, pf, n);
        checkPdf(scene, x, 0, camA * (w.y / kPi), what + " (the camera's cosine bounce escapes: per solid angle)");
        checkPdf(scene, x, 1, P * (1.0 / (4.0 * kPi)) * camA,
                 what + " (a background direction, P(l) / (4 pi), joined to the floor)");
        checkPdf(scene, x, 2, P * (1.0 / (4.0 * kPi)) * w.y / (kPi * R * R),
                 what + " (a background particle starts on a disk of radius R: |cos| / (pi R^2) at the floor)");
        checkPdf(scene, x, 3, 0.0, what);
        // The background seen straight through the pinhole: only the camera ray (s = 0).
        const DVec3 wCam = glm::normalize(DVec3(0.1, 0.3, 1.0));
        const ps::Path direct = {ps::backgroundVertex(scene, Vec3(wCam)), cam};
        const std::string whatDirect = "background -> pinhole";
        checkPdf(scene, direct, 0, cameraPdfW(scene, pc + wCam),
                 whatDirect + " (the camera ray's density per solid angle)");
        checkPdf(scene, direct, 1, 0.0,
                 whatDirect + " (a background direction cannot be joined to the pinhole, Eq. 6.12)");
        checkPdf(scene, direct, 2, 0.0, whatDirect);
    }
}
