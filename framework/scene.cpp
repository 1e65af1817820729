#include "scene.h"
#include "errors.h"
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <cstdio>
#include <sstream>

namespace ps {

namespace {
thread_local uint64_t tlsRays = 0;
}

uint64_t takeRayCount() {
    uint64_t n = tlsRays;
    tlsRays = 0;
    return n;
}

std::string Capabilities::describe() const {
    std::ostringstream os;
    auto list = [&](std::initializer_list<std::pair<bool, const char*>> items) {
        bool any = false;
        for (auto& [on, name] : items)
            if (on) {
                os << (any ? "," : "") << name;
                any = true;
            }
        if (!any) os << "none";
    };
    os << "lights=";
    list({{areaLights, "area"}, {pointLights, "point"}, {backgroundLight, "background"}});
    os << " bsdfs=";
    list({{diffuse, "diffuse"}, {glossy, "phong"}, {mirror, "mirror"}, {dielectric, "dielectric"}});
    os << " camera=" << cameraModel;
    if (unsampleablePaths()) os << " (has L S+ E paths no technique samples)";
    return os.str();
}

void Scene::finalize() {
    // BVH over all primitives.
    std::vector<AABB> boxes(prims.size());
    bounds = AABB();
    for (size_t i = 0; i < prims.size(); ++i) {
        const Primitive& pr = prims[i];
        boxes[i] = pr.shape == ShapeKind::Triangle ? triangles[pr.index].bounds() : spheres[pr.index].bounds();
        bounds.expand(boxes[i]);
    }
    bvh.build(boxes);
    items_.resize(prims.size());
    for (size_t i = 0; i < prims.size(); ++i) {
        const uint32_t p = bvh.order()[i];
        const Primitive& pr = prims[p];
        items_[i].prim = p;
        items_[i].material = pr.material;
        items_[i].light = pr.light;
        if (pr.shape == ShapeKind::Triangle) items_[i].tri = triangles[pr.index];
        else items_[i].sphere = pr.index;
    }

    // Bounding sphere of geometry and camera (background emission, light power).
    AABB all = bounds;
    all.expand(camera.position());
    center = all.center();
    radius = std::max(0.5f * glm::length(all.extent()), 1e-30f);

    // Float resolves a coordinate x only to ulp(x) ~ |x| 1.2e-7: a scene far from the origin
    // loses every feature smaller than that (a light 0.1 below a ceiling, moved by 1e7, lies on
    // it). Warn when the resolution is coarser than 1e-4 of the scene's size.
    warnings.clear();
    if (!prims.empty()) {
        const float far = std::max(maxAbsComponent(bounds.lo), maxAbsComponent(bounds.hi));
        const float ulp = std::nextafter(far, kInf) - far, size = glm::length(bounds.extent());
        if (size > 0.0f && ulp > 1e-4f * size) {
            char buf[320];
            std::snprintf(buf, sizeof buf,
                          "coordinates up to %.3g are resolved by float only to %.3g, %.2g of the scene's size %.3g: "
                          "features smaller than that merge (move the scene closer to the origin)",
                          double(far), double(ulp), double(ulp / size), double(size));
            warnings.push_back(buf);
        }
    }

    // Area lights: each one's primitives, chosen by area.
    caps = Capabilities();
    for (size_t l = 0; l < lights.size(); ++l) {
        Light& light = lights[l];
        if (light.kind == LightKind::Area) {
            std::vector<double> areas;
            for (uint32_t p : light.prims) {
                const Primitive& pr = prims[p];
                areas.push_back(pr.shape == ShapeKind::Triangle ? triangles[pr.index].area()
                                                                : spheres[pr.index].area());
            }
            light.primByArea = Distribution1D(areas);
            light.area = static_cast<float>(light.primByArea.total());
            caps.areaLights = true;
        } else if (light.kind == LightKind::Point) {
            caps.pointLights = true;
        } else {
            caps.backgroundLight = true;
            background = static_cast<int>(l);
        }
    }
    std::vector<double> power;
    for (size_t l = 0; l < lights.size(); ++l) {
        power.push_back(lightPower(*this, static_cast<int>(l)));
        // Radiance x area x pi in float: a light whose power overflows would be chosen with
        // probability NaN or 0 and render black without a single NaN sample to count.
        if (!std::isfinite(power.back()))
            throw InputError(path, lights[l].line,
                             "this light's power (radiance x area x pi) overflows float: "
                             "lower its emission or scale the scene's units");
    }
    lightSelection = Distribution1D(power);
    findSurfacePointLights();

    for (const Primitive& pr : prims) {
        switch (materials[pr.material].kind) {
        case BSDFKind::Diffuse: caps.diffuse = true; break;
        case BSDFKind::Phong: caps.glossy = true; break;
        case BSDFKind::Mirror: caps.mirror = true; break;
        case BSDFKind::Dielectric: caps.dielectric = true; break;
        }
    }
    caps.pinholeCamera = camera.isPinhole();
    caps.cameraModel = "pinhole";
    if (const CameraModel* m = camera.model()) {
        const std::string d = m->describe();
        caps.cameraModel = d.substr(0, d.find(' '));
    }
}

// A point light within 2^-17 of its coordinates' magnitude (64 float ulps) of a triangle's plane,
// over the triangle, or of a sphere, lies on it: the watertight test cannot tell on which side
// of that surface the light is, and rays from it would hit the surface at t = +-ulps at random
// (a point light exactly on the Cornell box's ceiling: lt 5 % dark, bpt 15 % bright against pt,
// which never shot a ray from the light). It is taken to be in the surface's plane: rays leaving
// it and shadow rays ending at it are offset off the surface by 2^-16 of that magnitude (twice
// the tolerance) to the side they go to (spawnRay, spawnRayTo), so the surface never sees it and
// each side gets the half of its light that goes there; a warning says so.
void Scene::findSurfacePointLights() {
    surfacePointLights.clear();
    constexpr double kTol = 0x1p-17;
    const double kSamePlane = std::cos(kPi / 180.0);  // normals within 1 degree: one plane
    for (size_t l = 0; l < lights.size(); ++l) {
        Light& light = lights[l];
        if (light.kind != LightKind::Point) continue;
        light.surfaceNormal = Vec3(0.0f);
        light.surfaceScale = 0.0f;
        light.surfacePlanes.clear();
        const glm::dvec3 p(light.position);
        const double pScale = maxAbsComponent(light.position);
        glm::dvec3 nSum(0.0), nFirst(0.0);
        double scale = 0.0;
        // The primitives in the BVH's leaves whose boxes, grown by the tolerance, hold the light,
        // taken in primitive order (so that nFirst and the sum do not depend on the tree).
        std::vector<uint32_t> near, stack;
        if (!bvh.nodes().empty()) stack.push_back(0);
        while (!stack.empty()) {
            const WideNode& node = bvh.nodes()[stack.back()];
            stack.pop_back();
            for (int k = 0; k < WideNode::kWidth; ++k) {
                const AABB b = node.box(k);
                const double grow =
                    kTol * std::max(pScale, double(std::max(maxAbsComponent(b.lo), maxAbsComponent(b.hi))));
                bool inside = true;
                for (int a = 0; a < 3; ++a) inside = inside && p[a] >= b.lo[a] - grow && p[a] <= b.hi[a] + grow;
                if (!inside) continue;
                if (node.slot[k].count == WideNode::kInner) stack.push_back(node.slot[k].child);
                else
                    for (uint32_t j = node.slot[k].child; j < node.slot[k].child + node.slot[k].count; ++j)
                        near.push_back(bvh.order()[j]);
            }
        }
        std::sort(near.begin(), near.end());
        std::vector<glm::dvec3> planes;  // distinct: no two within 1 degree (or back to back)
        for (uint32_t prim : near) {
            const Primitive& pr = prims[prim];
            glm::dvec3 n;
            double s;
            if (pr.shape == ShapeKind::Triangle) {
                const Triangle& t = triangles[pr.index];
                const glm::dvec3 p0(t.p0), e1 = glm::dvec3(t.p1) - p0, e2 = glm::dvec3(t.p2) - p0;
                const glm::dvec3 c = glm::cross(e1, e2);
                const double c2 = glm::dot(c, c);
                if (!(c2 > 0.0)) continue;
                s = std::max(pScale, double(t.errScale()));
                const double dist = glm::dot(c, p - p0) / std::sqrt(c2);
                if (std::abs(dist) > kTol * s) continue;
                // Barycentrics of the light's projection onto the plane (edges included).
                const glm::dvec3 q = p - p0;
                const double b1 = glm::dot(glm::cross(q, e2), c) / c2, b2 = glm::dot(glm::cross(e1, q), c) / c2;
                if (b1 < -kTol || b2 < -kTol || 1.0 - b1 - b2 < -kTol) continue;
                n = c / std::sqrt(c2);
            } else {
                const Sphere& sph = spheres[pr.index];
                const glm::dvec3 d = p - glm::dvec3(sph.center);
                const double len = glm::length(d);
                s = std::max(pScale, double(sph.errScale()));
                if (!(len > 0.0) || std::abs(len - double(sph.radius)) > kTol * s) continue;
                n = d / len;
            }
            if (scale == 0.0) nFirst = n;
            nSum += n;
            scale = std::max(scale, s);
            bool known = false;
            for (const glm::dvec3& m : planes) known = known || std::abs(glm::dot(m, n)) > kSamePlane;
            if (!known) planes.push_back(n);
        }
        if (scale == 0.0) continue;
        if (planes.size() > Light::kMaxSurfacePlanes)
            throw InputError(path, light.line,
                             "the point light lies where " + std::to_string(planes.size()) +
                                 " surfaces at different angles meet (a vertex of a mesh?): more than " +
                                 std::to_string(Light::kMaxSurfacePlanes) +
                                 " planes, whose sides its rays would have to leave from; move it off them");
        // On an edge or corner of surfaces at an angle: their mean normal (off all of them for
        // rays into the space they bound); back to back (the sum vanishes): the first one's.
        const double sumLen = glm::length(nSum);
        light.surfaceNormal = Vec3(sumLen > 1e-3 ? nSum / sumLen : nFirst);
        light.surfaceScale = float(8.0 * scale);  // offsetRayOrigin's 2^-19 x 8 = 2^-16 of it
        for (const glm::dvec3& n : planes) light.surfacePlanes.push_back(Vec3(n));
        surfacePointLights.push_back(int(l));
        const std::string which = light.line > 0 ? " of line " + std::to_string(light.line) : std::string();
        if (planes.size() == 1)
            warnings.push_back("the point light" + which +
                               " lies on a surface (within float rounding): it is taken to be in the surface's "
                               "plane, so that surface gets none of its light and half of it goes to the surface's "
                               "back; move it off the surface to light the surface itself");
        else
            warnings.push_back("the point light" + which + " lies on " + std::to_string(planes.size()) +
                               " surfaces at an edge or corner (within float rounding): it is taken to be in each "
                               "of their planes, so they get none of its light and each region between them gets "
                               "the light that goes into it; move it off them to light them");
    }
}

// The tolerance that put the light on its surfaces (findSurfacePointLights: 2^-17 of the magnitude).
bool inLightPlane(const Light& light, const Vec3& x) {
    const double tol = double(light.surfaceScale) * 0x1p-20;  // surfaceScale is 8 x the magnitude
    const glm::dvec3 d = glm::dvec3(x) - glm::dvec3(light.position);
    for (const Vec3& n : light.surfacePlanes)
        if (std::abs(glm::dot(glm::dvec3(n), d)) <= tol) return true;
    return false;
}

// A ray's end at a point light on surfaces (Light::surfacePlanes): its position plus the
// shortest offset d with s_i n_i . d >= eps for every plane i, s_i the side w goes to (+ when
// w lies in the plane). The shortest offset meets the bound with equality on at most three
// planes, so it is the shortest of the candidates that solve s_i n_i . d = eps on one, two or
// three of them and keep the bound on the rest (at most 8 + 28 + 56 for 8 planes; a light in a
// box's corner has 3 + 3 + 1). One plane: offsetRayOrigin's offset along its normal (the mean of
// the surfaces' normals, the plane's to rounding).
Vec3 lightRayPoint(const Light& light, const Vec3& w) {
    const size_t k = light.surfacePlanes.size();
    if (k == 0) return light.position;
    if (k == 1) return offsetRayOrigin(light.position, light.surfaceNormal, light.surfaceScale, w);  // the plane's
    const double eps = double(light.surfaceScale) * 0x1p-19;
    glm::dvec3 a[Light::kMaxSurfacePlanes];
    for (size_t i = 0; i < k; ++i) {
        const glm::dvec3 n(light.surfacePlanes[i]);
        a[i] = glm::dot(n, glm::dvec3(w)) >= 0.0 ? n : -n;
    }
    glm::dvec3 best(0.0);
    double bestLen2 = kInf;
    const auto consider = [&](const glm::dvec3& d) {
        const double len2 = glm::dot(d, d);
        if (!(len2 < bestLen2)) return;
        for (size_t i = 0; i < k; ++i)
            if (!(glm::dot(a[i], d) >= eps * (1.0 - 1e-9))) return;
        best = d;
        bestLen2 = len2;
    };
    for (size_t i = 0; i < k; ++i) {
        consider(eps * a[i]);
        for (size_t j = i + 1; j < k; ++j) {
            const double g = glm::dot(a[i], a[j]);
            if (1.0 + g > 1e-12) consider(eps / (1.0 + g) * (a[i] + a[j]));
            for (size_t m = j + 1; m < k; ++m) {
                // d with a_i.d = a_j.d = a_m.d = eps (Cramer's rule).
                const glm::dvec3 jm = glm::cross(a[j], a[m]), mi = glm::cross(a[m], a[i]), ij = glm::cross(a[i], a[j]);
                const double det = glm::dot(a[i], jm);
                if (std::abs(det) > 1e-9) consider(eps / det * (jm + mi + ij));
            }
        }
    }
    // No such offset within 256 eps (planes close to one another around a line, w almost in one
    // of them): the mean normal's side, as a single plane.
    if (!(bestLen2 <= 256.0 * 256.0 * eps * eps))
        return offsetRayOrigin(light.position, light.surfaceNormal, light.surfaceScale, w);
    return Vec3(glm::dvec3(light.position) + best);
}

namespace {
// The surface point at p on a triangle: one place for Scene::surfacePoint and for a closest hit
// (Scene::intersect, which reads the BVH item's copy of the triangle).
SurfacePoint trianglePoint(const Triangle& tri, const Vec3& p, uint32_t prim, int material, int light) {
    SurfacePoint sp;
    sp.prim = prim;
    sp.material = material;
    sp.light = light;
    sp.p = p;
    sp.n = tri.normal();
    sp.errScale = tri.errScale();
    return sp;
}
}  // namespace

SurfacePoint Scene::surfacePoint(uint32_t prim, const Vec3& p) const {
    const Primitive& pr = prims[prim];
    if (pr.shape == ShapeKind::Triangle) return trianglePoint(triangles[pr.index], p, prim, pr.material, pr.light);
    SurfacePoint sp;
    sp.prim = prim;
    sp.material = pr.material;
    sp.light = pr.light;
    const Sphere& s = spheres[pr.index];
    sp.n = glm::normalize(p - s.center);
    sp.p = s.center + s.radius * sp.n;  // reproject onto the surface
    sp.errScale = s.errScale();
    return sp;
}

float renderParameter(const RenderSettings& settings, const std::string& name, float fallback) {
    const auto it = settings.parameters.find(name);
    return it == settings.parameters.end() || it->second.empty() ? fallback : it->second[0];
}

std::vector<float> renderParameterValues(const RenderSettings& settings, const std::string& name,
                                         const std::vector<float>& fallback) {
    const auto it = settings.parameters.find(name);
    return it == settings.parameters.end() ? fallback : it->second;
}

std::string renderParameterProblem(const RenderParameter& p, const std::vector<float>& values) {
    if (values.size() != size_t(p.count))
        return "needs " + std::to_string(p.count) + (p.count == 1 ? " number" : " numbers") + " (" + p.valueNames +
               "), got " + std::to_string(values.size());
    for (float v : values)
        if (!std::isfinite(v)) return "needs finite numbers";
    return p.check ? p.check(values) : std::string();
}

bool Scene::closestHit(Ray& ray, SurfacePoint& sp) const {
    std::optional<WatertightRay> wr;  // built at the first triangle the ray reaches (many reach none)
    uint32_t hitItem = kNoPrimitive;
    float hb1 = 0.0f, hb2 = 0.0f;
    bvh.traverse(ray, false, [&](uint32_t i, Ray& r) {
        const Item& it = items_[i];
        float t, b1 = 0.0f, b2 = 0.0f;
        if (it.prim == r.ignorePrim) return false;
        if (it.sphere == kNoPrimitive) {
            if (!wr) wr.emplace(r);
            if (!intersectTriangle(r, *wr, it.tri, t, b1, b2)) return false;
        } else if (!intersectSphere(r, spheres[it.sphere], t)) {
            return false;
        }
        r.tMax = t;
        hitItem = i;
        hb1 = b1;
        hb2 = b2;
        return true;
    });
    if (hitItem == kNoPrimitive) return false;
    // Only now the surface point, once, for the closest hit.
    const Item& it = items_[hitItem];
    if (it.sphere != kNoPrimitive) {
        sp = surfacePoint(it.prim, ray.at(ray.tMax));
        return true;
    }
    // The point by barycentric interpolation: more accurate than o + t d far from the origin.
    const Vec3 p = (1.0f - hb1 - hb2) * it.tri.p0 + hb1 * it.tri.p1 + hb2 * it.tri.p2;
    sp = trianglePoint(it.tri, p, it.prim, it.material, it.light);
    return true;
}

bool Scene::anyHit(const Ray& ray) const {
    std::optional<WatertightRay> wr;
    Ray r = ray;
    return bvh.traverse(r, true, [&](uint32_t i, Ray& rr) {  // stops at the first hit
        const Item& it = items_[i];
        float t, b1, b2;
        if (it.prim == rr.ignorePrim) return false;
        if (it.sphere != kNoPrimitive) return intersectSphere(rr, spheres[it.sphere], t);
        if (!wr) wr.emplace(rr);
        return intersectTriangle(rr, *wr, it.tri, t, b1, b2);
    });
}

// The same two functions compiled a second time for AVX2 (x86-64 with GCC or Clang): the box
// test of bvh.h then takes one 8-wide instruction per line for a node's eight children where the
// x86-64 baseline (SSE2) takes two 4-wide ones (bench/README.md: 2-6 % more rays per second,
// measured with bvh_bench --tracer avx2).
// `flatten` inlines the traversal into them, so that it is compiled for AVX2 too. No fused
// multiply-add (FMA is not in the target, and ISO C++ mode, CMAKE_CXX_EXTENSIONS OFF, contracts
// nothing), so every operation rounds as in the baseline copy and both give the same bits
// (test_bvh.cpp fails when a * b + c is contracted; framework-same-bytes-baseline).
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PS_AVX2_COPY 1
__attribute__((target("avx2"), flatten)) bool Scene::closestHitAvx2(Ray& ray, SurfacePoint& sp) const {
    return closestHit(ray, sp);
}
__attribute__((target("avx2"), flatten)) bool Scene::anyHitAvx2(const Ray& ray) const { return anyHit(ray); }
#else
#define PS_AVX2_COPY 0
bool Scene::closestHitAvx2(Ray& ray, SurfacePoint& sp) const { return closestHit(ray, sp); }
bool Scene::anyHitAvx2(const Ray& ray) const { return anyHit(ray); }
#endif

namespace {
bool cpuHasAvx2() {
#if PS_AVX2_COPY
    __builtin_cpu_init();  // (needed before main, where this first runs)
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}
bool avx2Tracing = cpuHasAvx2() && !std::getenv("PATHSPACE_NO_AVX2");
}  // namespace

bool useAvx2Tracing(bool on) {
    avx2Tracing = on && cpuHasAvx2();
    return avx2Tracing;
}

bool Scene::intersect(Ray& ray, SurfacePoint& sp) const {
    ++tlsRays;
    return avx2Tracing ? closestHitAvx2(ray, sp) : closestHit(ray, sp);
}

bool Scene::occluded(const Ray& ray) const {
    if (ray.ignorePrim == kBlockedRay) return true;  // spawnRayTo: sees nothing, not traced
    ++tlsRays;
    return avx2Tracing ? anyHitAvx2(ray) : anyHit(ray);
}

namespace {
uint32_t ignoreFor(const Scene& s, const SurfacePoint& sp) {
    // A ray leaving a flat triangle cannot hit it again; a sphere can be hit from inside.
    return sp.prim != kNoPrimitive && s.prims[sp.prim].shape == ShapeKind::Triangle ? sp.prim : kNoPrimitive;
}

// The origin of a ray leaving sp in direction w: sp.p offset off its surface (offsetRayOrigin),
// and, on a triangle, off its edges too. A hit on an edge where two walls meet (a box's corner
// line) lies, up to rounding, in the plane of the other wall as well, and offset only along its
// own normal, the ray starts on (or a rounding error behind) that wall's plane: heading into
// that wall, its hit at t <= 0 is not one (rays are open at 0); heading away, the watertight test
// may still report a hit at t = +ulps, seen from the wall's back. Either way the path leaves a
// closed box (albedo 1 at maximum depth 1e5: 4e-8 per bounce, 0.4 % of the paths). So a point
// within 2^-22 of its coordinates' magnitude (a few float ulps) of an edge is first moved into
// its triangle, to the distance from the edge that the offset puts between it and its plane
// (2^-19 of that magnitude). Relative like offsetRayOrigin; every other point (all but ~1e-6 of
// the hits) is left exactly as it was. Triangles under twice that offset high are left alone.
Vec3 rayOrigin(const Scene& s, const SurfacePoint& sp, const Vec3& w) {
    Vec3 p = sp.p;
    if (sp.prim != kNoPrimitive && s.prims[sp.prim].shape == ShapeKind::Triangle && sp.errScale > 0.0f) {
        const Triangle& tri = s.triangles[s.prims[sp.prim].index];
        const glm::dvec3 v[3] = {glm::dvec3(tri.p0), glm::dvec3(tri.p1), glm::dvec3(tri.p2)};
        const glm::dvec3 n = glm::cross(v[1] - v[0], v[2] - v[0]);
        const double near = double(sp.errScale) * 0x1p-22, eps = double(sp.errScale) * 0x1p-19;
        glm::dvec3 q(sp.p);
        bool moved = false;
        for (int i = 0; i < 3; ++i) {
            const glm::dvec3& a = v[i];
            const glm::dvec3 e = v[(i + 1) % 3] - a;
            glm::dvec3 m = glm::cross(n, e);  // in the plane, towards the inside (counter-clockwise corners)
            // Far from this edge (nearly every hit): decided without a square root or a division,
            // proj = dist * |m| > near * |m| squared.
            const glm::dvec3 pa = glm::dvec3(sp.p) - a;
            const double len2 = glm::dot(m, m), proj = glm::dot(pa, m);
            if (proj > 0.0 && proj * proj > near * near * len2 * (1.0 + 0x1p-40)) continue;
            const double len = std::sqrt(len2);
            if (!(len > 0.0)) continue;
            m /= len;
            const double dist = glm::dot(pa, m);
            if (dist > near) continue;
            if (glm::dot(v[(i + 2) % 3] - a, m) <= 2.0 * eps) continue;  // too thin
            q += (eps - dist) * m;
            moved = true;
        }
        if (moved) p = Vec3(q);
    }
    return offsetRayOrigin(p, sp.n, sp.errScale, w);
}
}  // namespace

const Light* Scene::surfaceLight(const SurfacePoint& sp) const {
    if (sp.light < 0 || surfacePointLights.empty()) return nullptr;
    const Light& light = lights[size_t(sp.light)];
    return light.kind == LightKind::Point && light.surfaceScale > 0.0f ? &light : nullptr;
}

Ray Scene::spawnRay(const SurfacePoint& sp, const Vec3& dir) const {
    if (const Light* light = surfaceLight(sp)) return Ray(lightRayPoint(*light, dir), dir, kInf, kNoPrimitive);
    return Ray(rayOrigin(*this, sp, dir), dir, kInf, ignoreFor(*this, sp));
}

Ray Scene::spawnRayTo(const SurfacePoint& sp, const SurfacePoint& q) const {
    const Light* fromLight = surfaceLight(sp);
    const Light* toLight = surfaceLight(q);
    const Vec3 from = fromLight ? fromLight->position : sp.p, to = toLight ? toLight->position : q.p;
    const Vec3 o = fromLight ? lightRayPoint(*fromLight, to - from) : rayOrigin(*this, sp, to - from);
    const Vec3 target = toLight ? lightRayPoint(*toLight, from - to) : offsetRayOrigin(q.p, q.n, q.errScale, from - to);
    const Vec3 d = target - o;
    const float len = glm::length(d);
    // A point in a plane of the light does not see it: the light lies in that plane, so none of
    // its light arrives there (cos = 0). Traced, such a shadow ray would find the point's own
    // float rounding off the plane, a random cos ~ 2^-23 / d, and the estimators rare spikes
    // ~ 1/d^3 near the light (heavy tails no t-test can judge).
    const bool inPlane = (toLight && inLightPlane(*toLight, from)) || (fromLight && inLightPlane(*fromLight, to));
    return Ray(o, d / len, len, inPlane ? kBlockedRay : fromLight ? kNoPrimitive : ignoreFor(*this, sp));
}

Ray Scene::spawnRayTo(const SurfacePoint& sp, const Vec3& q) const {
    for (int l : surfacePointLights)
        if (lights[size_t(l)].position == q) {
            SurfacePoint target;
            target.p = q;
            target.light = l;
            return spawnRayTo(sp, target);
        }
    const Light* fromLight = surfaceLight(sp);
    const Vec3 from = fromLight ? fromLight->position : sp.p;
    const Vec3 o = fromLight ? lightRayPoint(*fromLight, q - from) : rayOrigin(*this, sp, q - from);
    const Vec3 d = q - o;
    const float len = glm::length(d);
    return Ray(o, d / len, len * (1.0f - 0x1p-20f), fromLight ? kNoPrimitive : ignoreFor(*this, sp));
}

int Scene::selectLight(float u, float& prob) const {
    if (lights.empty() || lightSelection.total() <= 0.0) {
        prob = 0.0f;
        return -1;
    }
    size_t i = lightSelection.sample(u);
    prob = lightSelection.pmf(i);
    return static_cast<int>(i);
}

}  // namespace ps
