#include "scene.h"
#include "errors.h"
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
    os << " camera=" << (pinholeCamera ? "pinhole" : "lens");
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

    for (const Primitive& pr : prims) {
        switch (materials[pr.material].kind) {
        case BSDFKind::Diffuse: caps.diffuse = true; break;
        case BSDFKind::Phong: caps.glossy = true; break;
        case BSDFKind::Mirror: caps.mirror = true; break;
        case BSDFKind::Dielectric: caps.dielectric = true; break;
        }
    }
    caps.pinholeCamera = camera.isPinhole();
}

SurfacePoint Scene::surfacePoint(uint32_t prim, const Vec3& p) const {
    const Primitive& pr = prims[prim];
    SurfacePoint sp;
    sp.prim = prim;
    sp.material = pr.material;
    sp.light = pr.light;
    if (pr.shape == ShapeKind::Triangle) {
        const Triangle& tri = triangles[pr.index];
        sp.p = p;
        sp.n = tri.normal();
        sp.errScale = tri.errScale();
    } else {
        const Sphere& s = spheres[pr.index];
        sp.n = glm::normalize(p - s.center);
        sp.p = s.center + s.radius * sp.n;  // reproject onto the surface
        sp.errScale = s.errScale();
    }
    return sp;
}

bool Scene::intersect(Ray& ray, SurfacePoint& sp) const {
    ++tlsRays;
    const WatertightRay wr(ray);
    uint32_t hitPrim = kNoPrimitive;
    float hb1 = 0.0f, hb2 = 0.0f;
    bvh.traverse(ray, false, [&](uint32_t i, Ray& r) {
        if (i == r.ignorePrim) return false;
        const Primitive& pr = prims[i];
        float t, b1 = 0.0f, b2 = 0.0f;
        if (pr.shape == ShapeKind::Triangle) {
            if (!intersectTriangle(r, wr, triangles[pr.index], t, b1, b2)) return false;
        } else if (!intersectSphere(r, spheres[pr.index], t)) {
            return false;
        }
        r.tMax = t;
        hitPrim = i;
        hb1 = b1;
        hb2 = b2;
        return true;
    });
    if (hitPrim == kNoPrimitive) return false;
    const Primitive& pr = prims[hitPrim];
    if (pr.shape == ShapeKind::Triangle) {
        // Barycentric interpolation is more accurate than o + t d far from the origin.
        const Triangle& tri = triangles[pr.index];
        sp = surfacePoint(hitPrim, (1.0f - hb1 - hb2) * tri.p0 + hb1 * tri.p1 + hb2 * tri.p2);
    } else {
        sp = surfacePoint(hitPrim, ray.at(ray.tMax));
    }
    return true;
}

bool Scene::occluded(const Ray& ray) const {
    ++tlsRays;
    const WatertightRay wr(ray);
    Ray r = ray;
    return bvh.traverse(r, true, [&](uint32_t i, Ray& rr) {
        if (i == rr.ignorePrim) return false;
        const Primitive& pr = prims[i];
        float t, b1, b2;
        return pr.shape == ShapeKind::Triangle ? intersectTriangle(rr, wr, triangles[pr.index], t, b1, b2)
                                               : intersectSphere(rr, spheres[pr.index], t);
    });
}

namespace {
uint32_t ignoreFor(const Scene& s, const SurfacePoint& sp) {
    // A ray leaving a flat triangle cannot hit it again; a sphere can be hit from inside.
    return sp.prim != kNoPrimitive && s.prims[sp.prim].shape == ShapeKind::Triangle ? sp.prim : kNoPrimitive;
}
}  // namespace

Ray Scene::spawnRay(const SurfacePoint& sp, const Vec3& dir) const {
    return Ray(offsetRayOrigin(sp.p, sp.n, sp.errScale, dir), dir, kInf, ignoreFor(*this, sp));
}

Ray Scene::spawnRayTo(const SurfacePoint& sp, const SurfacePoint& q) const {
    const Vec3 o = offsetRayOrigin(sp.p, sp.n, sp.errScale, q.p - sp.p);
    const Vec3 target = offsetRayOrigin(q.p, q.n, q.errScale, sp.p - q.p);
    const Vec3 d = target - o;
    const float len = glm::length(d);
    return Ray(o, d / len, len, ignoreFor(*this, sp));
}

Ray Scene::spawnRayTo(const SurfacePoint& sp, const Vec3& q) const {
    const Vec3 o = offsetRayOrigin(sp.p, sp.n, sp.errScale, q - sp.p);
    const Vec3 d = q - o;
    const float len = glm::length(d);
    return Ray(o, d / len, len * (1.0f - 0x1p-20f), ignoreFor(*this, sp));
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
