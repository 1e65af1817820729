// Lesson 6, graded: the area-measure pdf p_{s,t}(x) of fixed paths of length 2 and 3 in the room
// (lesson06.h) under every technique s = 0 ... k + 1, against an independent numerical
// evaluation: the sampling map of technique (s, t) takes random numbers u to the path's free
// vertices; its inverse u(x) is written here from the samplers' definitions alone (uniform
// point on the light, cosine-weighted emission and diffuse bounces, the Phong lobe, a uniform
// raster position), and p_{s,t}(x) = P(light) |det du/dx| with the Jacobian taken by central
// finite differences in double, every free vertex moved in 2D coordinates of its plane (area
// measure, Eq. 6.7). No cosine, distance or solid-angle formula of the lesson appears here.
#include "lesson06.h"

using namespace lesson06;

namespace {

DVec3 d3(const Vec3& v) { return DVec3(v); }

enum class Kind { AreaLight, PointLight, Diffuse, Phong, Pinhole };
struct Vtx {
    Kind kind;
    DVec3 p, n;    // n: the surface normal (diffuse, Phong, area light)
    DVec3 e1, e2;  // orthonormal tangents of the vertex's plane (free vertices)
};

// Any orthonormal pair perpendicular to the unit a.
void basis(const DVec3& a, DVec3& t1, DVec3& t2) {
    t1 = glm::normalize(std::abs(a.x) > 0.5 ? glm::cross(a, DVec3(0, 1, 0)) : glm::cross(a, DVec3(1, 0, 0)));
    t2 = glm::cross(a, t1);
}
double angle01(double y, double x) { return std::atan2(y, x) / (2.0 * kPi); }
// Inverse of cosine-weighted hemisphere sampling about n (Malley, polar): u = (sin^2 theta, phi / 2 pi).
void invCosine(const DVec3& n, const DVec3& w, std::vector<double>& u) {
    DVec3 t1, t2;
    basis(n, t1, t2);
    const double x = glm::dot(w, t1), y = glm::dot(w, t2);
    u.push_back(x * x + y * y);
    u.push_back(angle01(y, x));
}
// Inverse of uniform sphere sampling: u = ((1 - cos theta) / 2, phi / 2 pi).
void invSphere(const DVec3& w, std::vector<double>& u) {
    u.push_back(0.5 * (1.0 - w.z));
    u.push_back(angle01(w.y, w.x));
}
// Inverse of Phong lobe sampling about r: u = (cos^(e+1) alpha, phi / 2 pi).
void invPhong(const DVec3& r, double e, const DVec3& w, std::vector<double>& u) {
    DVec3 t1, t2;
    basis(r, t1, t2);
    u.push_back(std::pow(glm::dot(w, r), e + 1.0));
    u.push_back(angle01(glm::dot(w, t2), glm::dot(w, t1)));
}
DVec3 reflectD(const DVec3& w, const DVec3& n) { return 2.0 * glm::dot(w, n) * n - w; }

// The random numbers that make technique s produce the path with vertex positions p (Eq. 6.8).
std::vector<double> randomNumbersOf(const ps::Scene& scene, const std::vector<Vtx>& v, const std::vector<DVec3>& p,
                                    int s) {
    const int k = int(v.size()) - 1;
    std::vector<double> u;
    auto dir = [&](int from, int to) { return glm::normalize(p[size_t(to)] - p[size_t(from)]); };
    auto scatter = [&](int at, const DVec3& wFrom, const DVec3& wTo) {
        const Vtx& x = v[size_t(at)];
        const DVec3 ns = glm::dot(x.n, wFrom) < 0 ? -x.n : x.n;
        if (x.kind == Kind::Phong) invPhong(reflectD(wFrom, ns), 4.0, wTo, u);
        else invCosine(ns, wTo, u);
    };
    if (s >= 1) {
        if (v[0].kind == Kind::AreaLight) {  // uniform on the 1 x 1 light (area 1: du = dA)
            u.push_back(glm::dot(p[0], v[0].e1));
            u.push_back(glm::dot(p[0], v[0].e2));
        }
        if (s >= 2) {
            if (v[0].kind == Kind::AreaLight) invCosine(v[0].n, dir(0, 1), u);
            else invSphere(dir(0, 1), u);
        }
        for (int i = 1; i <= s - 2; ++i) scatter(i, dir(i, i - 1), dir(i, i + 1));
    }
    if (k + 1 - s >= 2) {
        // Uniform raster position over the image: u = raster / (width, height).
        const DVec3 e = d3(scene.camera.position()), f = glm::normalize(DVec3(0, 1, 0) - e);
        const DVec3 right = glm::normalize(glm::cross(f, DVec3(0, 1, 0))), up = glm::cross(right, f);
        const double tanY = std::tan(30.0 * kPi / 180.0), tanX = tanY;  // fov 60, square
        const DVec3 d = p[size_t(k) - 1] - e;
        const double z = glm::dot(d, f);
        u.push_back((glm::dot(d, right) / z / tanX + 1.0) * 0.5);
        u.push_back((1.0 - glm::dot(d, up) / z / tanY) * 0.5);
        for (int j = k - 1; j >= s + 1; --j) scatter(j, dir(j, j + 1), dir(j, j - 1));
    }
    return u;
}

double determinant(std::vector<std::vector<double>> a) {
    const size_t n = a.size();
    double det = 1.0;
    for (size_t c = 0; c < n; ++c) {
        size_t piv = c;
        for (size_t r = c + 1; r < n; ++r)
            if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
        if (a[piv][c] == 0.0) return 0.0;
        if (piv != c) {
            std::swap(a[piv], a[c]);
            det = -det;
        }
        det *= a[c][c];
        for (size_t r = c + 1; r < n; ++r) {
            const double m = a[r][c] / a[c][c];
            for (size_t q = c; q < n; ++q) a[r][q] -= m * a[c][q];
        }
    }
    return det;
}

// p_{s,t} by the finite-difference Jacobian of u(x) over the free vertices' plane coordinates.
double numericPdf(const ps::Scene& scene, const std::vector<Vtx>& v, int s) {
    std::vector<DVec3> p;
    std::vector<std::pair<size_t, DVec3>> freeDims;  // (vertex, tangent)
    for (size_t i = 0; i < v.size(); ++i) {
        p.push_back(v[i].p);
        if (v[i].kind != Kind::PointLight && v[i].kind != Kind::Pinhole) {
            freeDims.push_back({i, v[i].e1});
            freeDims.push_back({i, v[i].e2});
        }
    }
    const std::vector<double> u0 = randomNumbersOf(scene, v, p, s);
    REQUIRE_MESSAGE(u0.size() == freeDims.size(),
                    "test setup: " << u0.size() << " random numbers for " << freeDims.size() << " coordinates");
    const size_t n = u0.size();
    std::vector<std::vector<double>> J(n, std::vector<double>(n));
    const double h = 1e-6;
    for (size_t c = 0; c < n; ++c) {
        std::vector<DVec3> plus = p, minus = p;
        plus[freeDims[c].first] += h * freeDims[c].second;
        minus[freeDims[c].first] -= h * freeDims[c].second;
        const std::vector<double> up = randomNumbersOf(scene, v, plus, s), um = randomNumbersOf(scene, v, minus, s);
        for (size_t r = 0; r < n; ++r) {
            double d = up[r] - um[r];
            if (r % 2 == 1) d -= std::round(d);  // the angle wraps around at +-1/2
            J[r][c] = d / (2.0 * h);
        }
    }
    double P = 1.0;
    if (s >= 1) {
        const int l = lightOfKind(scene, v[0].kind == Kind::AreaLight ? ps::LightKind::Area : ps::LightKind::Point);
        P = scene.lightSelectionProb(l);
    }
    return P * std::abs(determinant(J));
}

struct TestPath {
    std::string name;
    std::vector<Vtx> v;
    ps::Path x;
};

TestPath makePath(const std::string& name, const std::vector<std::pair<Kind, Vec3>>& spec) {
    const ps::Scene& scene = room();
    TestPath t;
    t.name = name;
    for (const auto& [kind, p] : spec) {
        Vtx v;
        v.kind = kind;
        v.p = d3(p);
        switch (kind) {
        case Kind::AreaLight:
            t.x.push_back(areaLightPoint(scene, p));
            v.n = d3(t.x.back().sp.n), v.e1 = DVec3(1, 0, 0), v.e2 = DVec3(0, 0, 1);
            break;
        case Kind::PointLight:
            t.x.push_back(pointLightVertex(scene));
            v.p = d3(t.x.back().sp.p);
            break;
        case Kind::Diffuse:
            t.x.push_back(surface(scene, p, Vec3(0, 1, 0), "floor"));
            v.n = DVec3(0, 1, 0), v.e1 = DVec3(1, 0, 0), v.e2 = DVec3(0, 0, 1);
            break;
        case Kind::Phong:
            t.x.push_back(surface(scene, p, Vec3(0, 0, -1), "wall"));
            v.n = DVec3(0, 0, -1), v.e1 = DVec3(1, 0, 0), v.e2 = DVec3(0, 1, 0);
            break;
        case Kind::Pinhole:
            t.x.push_back(pinhole(scene));
            v.p = d3(t.x.back().sp.p);
            break;
        }
        t.v.push_back(v);
    }
    return t;
}

void checkAllTechniques(const TestPath& t) {
    const ps::Scene& scene = room();
    const int k = int(t.x.size()) - 1;
    for (int s = 0; s <= k + 1; ++s) {
        const int tt = k + 1 - s;
        const double got = ps::pdfTechnique(scene, t.x, s);
        INFO(t.name << ", technique (s, t) = (" << s << ", " << tt << "), path " << describe(t.x));
        CHECK_MESSAGE(std::isfinite(got), "expected a finite pdf, got " << got);
        const bool cannot = tt == 0 || (s == 0 && t.v[0].kind == Kind::PointLight);
        if (cannot) {
            CHECK_MESSAGE(got == 0.0, "this technique cannot sample the path ("
                                          << std::string(tt == 0 ? "t = 0: no ray hits a pinhole"
                                                                 : "s = 0: no ray hits a point light")
                                          << "): expected p = 0 exactly, got " << num(got));
            continue;
        }
        const double expected = numericPdf(scene, t.v, s);
        REQUIRE_MESSAGE(expected > 0.0, "test setup: the path should be sampleable");
        CHECK_MESSAGE(close(got, expected, 2e-3), "expected p_{s,t} = P(light) |det du/dx| = "
                                                      << num(expected)
                                                      << " (finite-difference Jacobian of the sampling map), got "
                                                      << num(got) << " (ratio " << num(got / expected) << ")");
    }
}

// Every technique, and s outside 0 ... k + 1, gives p = 0 exactly: paths no technique samples.
void checkNone(const std::string& name, const ps::Path& x, const std::string& why) {
    const int k = int(x.size()) - 1;
    for (int s = -1; s <= k + 2; ++s) {
        const double got = ps::pdfTechnique(room(), x, s);
        CHECK_MESSAGE(got == 0.0, name << ", s = " << s << ", path " << describe(x) << ": " << why
                                       << ": expected p = 0 exactly, got " << num(got));
    }
}

}  // namespace

TEST_CASE(
    "path space: p_{s,t} of paths of length 2 under every technique equals the Jacobian of the sampling map (Eq. 6.7-6.10) [3 pts]") {
    checkAllTechniques(makePath("area light -> floor -> pinhole", {{Kind::AreaLight, Vec3(0.1f, 2.0f, -0.2f)},
                                                                   {Kind::Diffuse, Vec3(0.3f, 0.0f, 0.4f)},
                                                                   {Kind::Pinhole, Vec3(0.0f)}}));
    checkAllTechniques(makePath(
        "point light -> floor -> pinhole",
        {{Kind::PointLight, Vec3(0.0f)}, {Kind::Diffuse, Vec3(-0.5f, 0.0f, 0.9f)}, {Kind::Pinhole, Vec3(0.0f)}}));
    checkAllTechniques(makePath("area light -> glossy wall -> pinhole", {{Kind::AreaLight, Vec3(-0.3f, 2.0f, 0.4f)},
                                                                         {Kind::Phong, Vec3(-0.4f, 0.8f, 2.0f)},
                                                                         {Kind::Pinhole, Vec3(0.0f)}}));
}

TEST_CASE(
    "path space: p_{s,t} of paths of length 3 under every technique equals the Jacobian of the sampling map (Eq. 6.7-6.10) [3 pts]") {
    checkAllTechniques(
        makePath("area light -> glossy wall -> floor -> pinhole", {{Kind::AreaLight, Vec3(0.1f, 2.0f, -0.2f)},
                                                                   {Kind::Phong, Vec3(-0.4f, 0.8f, 2.0f)},
                                                                   {Kind::Diffuse, Vec3(0.3f, 0.0f, 0.4f)},
                                                                   {Kind::Pinhole, Vec3(0.0f)}}));
    checkAllTechniques(
        makePath("area light -> floor -> glossy wall -> pinhole", {{Kind::AreaLight, Vec3(0.2f, 2.0f, 0.1f)},
                                                                   {Kind::Diffuse, Vec3(-0.2f, 0.0f, 1.2f)},
                                                                   {Kind::Phong, Vec3(0.3f, 0.6f, 2.0f)},
                                                                   {Kind::Pinhole, Vec3(0.0f)}}));
    checkAllTechniques(
        makePath("point light -> glossy wall -> floor -> pinhole", {{Kind::PointLight, Vec3(0.0f)},
                                                                    {Kind::Phong, Vec3(0.5f, 1.1f, 2.0f)},
                                                                    {Kind::Diffuse, Vec3(0.1f, 0.0f, 0.5f)},
                                                                    {Kind::Pinhole, Vec3(0.0f)}}));
    // Paths no technique can sample, and techniques outside 0 ... k + 1: p = 0 exactly. The mirror
    // (x = -2) at the point where light from (0, 2, 0) reflects to the floor point (0.3, 0, 0.4),
    // joined instead to (0.6, 0, 0.4): the two directions there are no reflected pair, which a
    // delta lobe never samples (Eq. 6.11), from either side.
    const ps::Scene& scene = room();
    const DVec3 p0(0.0, 2.0, 0.0), img(-4.3, 0.0, 0.4);
    const DVec3 pm = p0 + (2.0 / 4.3) * (img - p0);
    const ps::PathVertex mirror = surface(scene, Vec3(pm), Vec3(1, 0, 0), "mirror");
    const ps::PathVertex floor = surface(scene, Vec3(0.6f, 0.0f, 0.4f), Vec3(0, 1, 0), "floor");
    checkNone("area light -> mirror off its reflection -> floor -> pinhole",
              {areaLightPoint(scene, Vec3(p0)), mirror, floor, pinhole(scene)},
              "the directions at the mirror are not a reflected pair");
    checkNone("floor -> glossy wall -> floor -> pinhole",
              {surface(scene, Vec3(0.3f, 0.0f, 0.4f), Vec3(0, 1, 0), "floor"),
               surface(scene, Vec3(-0.4f, 0.8f, 2.0f), Vec3(0, 0, -1), "wall"), floor, pinhole(scene)},
              "x0 is on no light");
    checkNone("the pinhole alone", {pinhole(scene)}, "one vertex is no path (k = 0)");
    const TestPath two = makePath("area light -> floor -> pinhole", {{Kind::AreaLight, Vec3(0.1f, 2.0f, -0.2f)},
                                                                     {Kind::Diffuse, Vec3(0.3f, 0.0f, 0.4f)},
                                                                     {Kind::Pinhole, Vec3(0.0f)}});
    for (int s : {-1, 4}) {
        const double got = ps::pdfTechnique(scene, two.x, s);
        CHECK_MESSAGE(got == 0.0, two.name << ": technique s = " << s << " of a path with k = 2 (s from 0 to 3): "
                                           << "expected p = 0 exactly, got " << num(got));
    }
}
