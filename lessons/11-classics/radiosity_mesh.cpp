// Lesson 11 — radiosity's elements (plumbing: read it, nothing to write here): what radiosity
// accepts of a scene, every quad cut into nu x nv elements by bilinear coordinates, a uniform
// point on an element, and the element a ray hits.
//
// A quad's corners P1..P4 (scene file order) give the bilinear map
//     P(u, v) = (1-u)(1-v) P1 + u (1-v) P2 + u v P3 + (1-u) v P4,   (u, v) in [0,1]^2,
// u along the edge 1-2, v along 1-4. On a flat quad its lines of constant u or v are straight,
// so element (a, b), the image of [a/nu, (a+1)/nu] x [b/nv, (b+1)/nv], is the quadrilateral of
// its four corners. A quad that is not quite flat (the Cornell box's red wall is bent by 3 mm in
// 550) is two triangles of the scene: points sampled on an element are projected onto the
// triangle under them, so that rays start on the surface the renderer sees.
#include <algorithm>
#include <cmath>
#include "11-classics/radiosity.h"
#include "errors.h"
#include "warps.h"

namespace ps {

namespace {

using DVec3 = glm::dvec3;

DVec3 bilinear(const Quad& q, double u, double v) {
    const DVec3 p0(q.corners[0]), p1(q.corners[1]), p2(q.corners[2]), p3(q.corners[3]);
    return (1 - u) * (1 - v) * p0 + u * (1 - v) * p1 + u * v * p2 + (1 - u) * v * p3;
}

double cross2(const glm::dvec2& a, const glm::dvec2& b) { return a.x * b.y - a.y * b.x; }

// The quad's normal: its first triangle's (the scene's, Scene::Quad).
DVec3 quadNormal(const Quad& q) {
    return glm::normalize(
        glm::cross(DVec3(q.corners[1]) - DVec3(q.corners[0]), DVec3(q.corners[2]) - DVec3(q.corners[0])));
}

// Whether the quad is convex: its corners turn the same way (seen along its normal) at all four.
bool convex(const Quad& q) {
    const DVec3 n = quadNormal(q);
    for (int k = 0; k < 4; ++k) {
        const DVec3 a(q.corners[k]), b(q.corners[(k + 1) % 4]), c(q.corners[(k + 2) % 4]);
        if (!(glm::dot(glm::cross(b - a, c - b), n) > 0.0)) return false;
    }
    return true;
}

// (u, v) of a point p of the quad (inverse of the bilinear map, in the quad's plane), clamped
// to [0, 1]^2.
glm::dvec2 inverseBilinear(const Quad& q, const DVec3& p) {
    const DVec3 n = quadNormal(q);
    const DVec3 o(q.corners[0]);
    const DVec3 e1 = glm::normalize(DVec3(q.corners[1]) - o), e2 = glm::cross(n, e1);
    auto flat = [&](const DVec3& x) { return glm::dvec2(glm::dot(x - o, e1), glm::dot(x - o, e2)); };
    const glm::dvec2 a(0.0), b = flat(DVec3(q.corners[1])), c = flat(DVec3(q.corners[2])),
                             d = flat(DVec3(q.corners[3]));
    const glm::dvec2 e = b - a, f = d - a, g = a - b + c - d, h = flat(p) - a;
    // h = u e + v f + u v g; eliminating u gives k2 v^2 + k1 v + k0 = 0.
    const double k2 = cross2(g, f), k1 = cross2(e, f) + cross2(h, g), k0 = cross2(h, e);
    const double scale = std::abs(cross2(e, f)) + std::abs(cross2(g, f));
    double v;
    if (std::abs(k2) <= 1e-12 * scale) {  // a parallelogram (or close): linear
        v = -k0 / k1;
    } else {
        const double w = std::sqrt(std::max(0.0, k1 * k1 - 4.0 * k0 * k2));
        const double v1 = (-k1 - w) / (2.0 * k2), v2 = (-k1 + w) / (2.0 * k2);
        auto outside = [](double x) { return x < 0.0 ? -x : (x > 1.0 ? x - 1.0 : 0.0); };
        v = outside(v1) <= outside(v2) ? v1 : v2;
    }
    const glm::dvec2 du = e + v * g;  // h - v f = u (e + v g)
    const double u = glm::dot(h - v * f, du) / glm::dot(du, du);
    return glm::clamp(glm::dvec2(u, v), 0.0, 1.0);
}

std::string materialKind(BSDFKind k) {
    switch (k) {
    case BSDFKind::Diffuse: return "diffuse";
    case BSDFKind::Phong: return "phong";
    case BSDFKind::Mirror: return "mirror";
    case BSDFKind::Dielectric: return "dielectric";
    }
    return "unknown";
}

const char* kWhat = "radiosity handles diffuse quads lit by quads with emission (lesson 11)";

}  // namespace

void checkRadiosityScene(const Scene& scene) {
    const std::string& path = scene.path;
    if (!scene.spheres.empty())
        throw InputError(path, 0,
                         std::to_string(scene.spheres.size()) + " sphere(s): " + kWhat + ", and a sphere is no quad");
    std::vector<char> inQuad(scene.prims.size(), 0);
    for (const Quad& q : scene.quads) inQuad[q.prim] = inQuad[q.prim + 1] = 1;
    size_t loose = 0;
    for (size_t p = 0; p < scene.prims.size(); ++p) loose += !inQuad[p];
    if (loose > 0)
        throw InputError(path, 0,
                         std::to_string(loose) + " triangle(s) not from a 'quad' statement ('triangle' or 'mesh'): " +
                             kWhat + " (each quad is a patch)");
    for (const Quad& q : scene.quads) {
        const Material& m = scene.materials[size_t(scene.prims[q.prim].material)];
        if (m.kind != BSDFKind::Diffuse)
            throw InputError(path, q.line,
                             "material '" + m.name + "' is " + materialKind(m.kind) + ": " + kWhat +
                                 " (radiosity assumes light leaves every surface equally in all directions)");
        if (!convex(q))
            throw InputError(path, q.line,
                             "a concave quad: radiosity cuts quads into elements by bilinear coordinates, which "
                             "needs a convex quad (split it into two)");
    }
    for (const Light& l : scene.lights) {
        if (l.kind == LightKind::Point)
            throw InputError(path, l.line,
                             std::string("a point light: ") + kWhat + " (a point has no area to be a patch)");
        if (l.kind == LightKind::Background)
            throw InputError(path, l.line, std::string("a background light: ") + kWhat);
    }
}

ElementMesh::ElementMesh(const Scene& scene, int nu, int nv) : scene_(&scene), nu_(nu), nv_(nv) {
    checkRadiosityScene(scene);
    if (nu < 1 || nv < 1 || nu > kMaxElements || nv > kMaxElements)
        throw InputError(scene.path, 0,
                         "radiosity: elements " + std::to_string(nu) + " x " + std::to_string(nv) +
                             " per quad; each must be from 1 to " + std::to_string(kMaxElements));
    quadOfPrim_.assign(scene.prims.size(), -1);
    elements_.reserve(scene.quads.size() * size_t(nu) * size_t(nv));
    for (size_t qi = 0; qi < scene.quads.size(); ++qi) {
        const Quad& q = scene.quads[qi];
        quadOfPrim_[q.prim] = quadOfPrim_[q.prim + 1] = int(qi);
        const Primitive& pr = scene.prims[q.prim];
        const Material& m = scene.materials[size_t(pr.material)];
        const Color Le = pr.light >= 0 ? scene.lights[size_t(pr.light)].Le : Color(0.0f);
        const Vec3 n = scene.triangles[pr.index].normal();
        for (int b = 0; b < nv; ++b)
            for (int a = 0; a < nu; ++a) {
                Element e;
                e.quad = int(qi);
                e.a = a;
                e.b = b;
                const double u0 = double(a) / nu, u1 = double(a + 1) / nu, v0 = double(b) / nv, v1 = double(b + 1) / nv;
                const DVec3 c[4] = {bilinear(q, u0, v0), bilinear(q, u1, v0), bilinear(q, u1, v1), bilinear(q, u0, v1)};
                for (int k = 0; k < 4; ++k) e.corners[k] = Vec3(c[k]);
                e.area = float(0.5 * glm::length(glm::cross(c[1] - c[0], c[2] - c[0])) +
                               0.5 * glm::length(glm::cross(c[2] - c[0], c[3] - c[0])));
                e.normal = n;
                e.rho = m.albedo;
                e.E = kPi * Le;
                elements_.push_back(e);
            }
    }
}

SurfacePoint ElementMesh::samplePoint(int i, const Vec2& uIn) const {
    const Element& e = elements_[size_t(i)];
    const DVec3 c0(e.corners[0]), c1(e.corners[1]), c2(e.corners[2]), c3(e.corners[3]);
    const double a1 = glm::length(glm::cross(c1 - c0, c2 - c0)), a2 = glm::length(glm::cross(c2 - c0, c3 - c0));
    // The element's triangle (c0, c1, c2) or (c0, c2, c3), chosen in proportion to its area by
    // u.x, which is then stretched back to [0, 1).
    const double p1 = a1 / (a1 + a2);
    Vec2 u = uIn;
    DVec3 t1 = c1, t2 = c2;
    if (double(u.x) < p1) {
        u.x = float(double(u.x) / p1);
    } else {
        u.x = float((double(u.x) - p1) / (1.0 - p1));
        t1 = c2;
        t2 = c3;
    }
    u.x = std::min(u.x, 0x1.fffffep-1f);
    const Vec2 bary = sampleUniformTriangle(u);
    DVec3 p = (1.0 - double(bary.x) - double(bary.y)) * c0 + double(bary.x) * t1 + double(bary.y) * t2;
    // The scene's triangle under p: (P1, P2, P3) if p is on P2's side of the diagonal P1-P3,
    // else (P1, P3, P4); p projected onto its plane.
    const Quad& q = scene_->quads[size_t(e.quad)];
    const DVec3 P0(q.corners[0]), P2(q.corners[2]);
    const DVec3 n = quadNormal(q);
    const bool first = glm::dot(glm::cross(P2 - P0, p - P0), n) <= 0.0;
    const uint32_t prim = first ? q.prim : q.prim + 1;
    const Triangle& tri = scene_->triangles[scene_->prims[prim].index];
    const DVec3 tn = glm::normalize(glm::cross(DVec3(tri.p1) - DVec3(tri.p0), DVec3(tri.p2) - DVec3(tri.p0)));
    p -= glm::dot(p - DVec3(tri.p0), tn) * tn;
    return scene_->surfacePoint(prim, Vec3(p));
}

int ElementMesh::elementAt(const SurfacePoint& sp, const Vec3& d) const {
    if (sp.prim >= quadOfPrim_.size()) return -1;
    const int qi = quadOfPrim_[sp.prim];
    if (qi < 0) return -1;
    if (!(glm::dot(sp.n, d) < 0.0f)) return -1;  // arrives at the back: one-sided elements
    const glm::dvec2 uv = inverseBilinear(scene_->quads[size_t(qi)], DVec3(sp.p));
    const int a = std::min(nu_ - 1, int(uv.x * nu_)), b = std::min(nv_ - 1, int(uv.y * nv_));
    return first(qi) + a + nu_ * b;
}

}  // namespace ps
