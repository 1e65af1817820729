// Tests of framework/bvh.h through Scene::intersect / Scene::occluded: the BVH must return
// exactly what a brute-force loop over all primitives returns.
#include <doctest/doctest.h>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <numeric>
#include <string>
#include <vector>
#include "rng.h"
#include "seed.h"
#include "scene.h"

using namespace ps;

namespace {

Vec3 randomUnit(Rng& rng) {
    const float z = 1.0f - 2.0f * rng.uniform(), r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const float phi = 2.0f * kPi * rng.uniform();
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}
Vec3 randomIn(Rng& rng, const Vec3& lo, const Vec3& hi) {
    return lo + (hi - lo) * Vec3{rng.uniform(), rng.uniform(), rng.uniform()};
}

// A scene of the given triangles and spheres, one diffuse material, no lights.
Scene makeScene(const std::vector<Triangle>& tris, const std::vector<Sphere>& spheres) {
    Scene s;
    Material m;
    m.kind = BSDFKind::Diffuse;
    s.materials.push_back(m);
    s.triangles = tris;
    s.spheres = spheres;
    for (uint32_t i = 0; i < tris.size(); ++i) s.prims.push_back({ShapeKind::Triangle, i, 0, -1});
    for (uint32_t i = 0; i < spheres.size(); ++i) s.prims.push_back({ShapeKind::Sphere, i, 0, -1});
    s.camera = Camera(Vec3(0, 0, -10), Vec3(0, 0, 0), Vec3(0, 1, 0), 40.0f, 8, 8);
    s.finalize();
    return s;
}

// The closest hit by testing every primitive with the full ray: prim index and t.
struct BruteHit {
    uint32_t prim = kNoPrimitive;
    float t = kInf;
};
BruteHit bruteClosest(const Scene& s, const Ray& ray) {
    const WatertightRay wr(ray);
    BruteHit best;
    for (uint32_t i = 0; i < s.prims.size(); ++i) {
        if (i == ray.ignorePrim) continue;
        const Primitive& p = s.prims[i];
        float t, b1, b2;
        const bool hit = p.shape == ShapeKind::Triangle ? intersectTriangle(ray, wr, s.triangles[p.index], t, b1, b2)
                                                        : intersectSphere(ray, s.spheres[p.index], t);
        if (hit && t < best.t) {
            best.t = t;
            best.prim = i;
        }
    }
    return best;
}

// Compares Scene::intersect and Scene::occluded with brute force for one ray; returns the
// number of disagreements (and reports the first few).
int compareRay(const Scene& s, const Ray& ray, int& reported) {
    const BruteHit ref = bruteClosest(s, ray);
    Ray r = ray;
    SurfacePoint sp;
    const bool hit = s.intersect(r, sp);
    const bool occ = s.occluded(ray);
    int bad = 0;
    const bool refHit = ref.prim != kNoPrimitive;
    std::string what;
    if (hit != refHit) {
        ++bad;
        what = "closest: hit " + std::to_string(hit) + " vs brute force " + std::to_string(refHit);
    } else if (hit) {
        // t must match bit for bit (the same primitive test); a different primitive only when its
        // t is the same (coincident or touching primitives).
        if (r.tMax != ref.t) {
            ++bad;
            what = "t " + std::to_string(r.tMax) + " vs brute force " + std::to_string(ref.t);
        } else if (sp.prim != ref.prim && bruteClosest(s, Ray(ray.o, ray.d, kInf, ref.prim)).t != ref.t) {
            ++bad;  // a different primitive must be one with the same t (brute force without ref.prim finds it)
            what = "a different primitive at the same t that brute force does not see there";
        }
    }
    if (occ != refHit) {
        ++bad;
        what += " occluded " + std::to_string(occ) + " vs brute force " + std::to_string(refHit);
    }
    if (bad && reported++ < 5)
        FAIL_CHECK("ray o = (" << ray.o.x << ", " << ray.o.y << ", " << ray.o.z << ") d = (" << ray.d.x << ", "
                               << ray.d.y << ", " << ray.d.z << ") tMax " << ray.tMax << ": " << what << " (BVH prim "
                               << sp.prim << ", brute-force prim " << ref.prim << ")");
    return bad;
}

// Rays for a scene inside box [lo, hi]: half aimed at a random point of a random primitive,
// half random; some with a finite tMax, some ignoring a primitive.
std::vector<Ray> makeRays(const Scene& s, int n, Rng& rng) {
    std::vector<Ray> rays;
    const Vec3 lo = s.bounds.lo, hi = s.bounds.hi, ext = hi - lo;
    for (int k = 0; k < n; ++k) {
        Ray r;
        if (k % 2 == 0 && !s.prims.empty()) {
            const uint32_t pi = rng.nextU32() % s.prims.size();
            const Primitive& p = s.prims[pi];
            Vec3 target;
            if (p.shape == ShapeKind::Triangle) {
                const Triangle& t = s.triangles[p.index];
                const float b1 = rng.uniform(), b2 = (1.0f - b1) * rng.uniform();
                target = (1.0f - b1 - b2) * t.p0 + b1 * t.p1 + b2 * t.p2;
            } else {
                target = s.spheres[p.index].center + s.spheres[p.index].radius * randomUnit(rng);
            }
            r.o = randomIn(rng, lo - 0.5f * ext, hi + 0.5f * ext);
            const Vec3 d = target - r.o;
            if (glm::length(d) == 0.0f) continue;
            r.d = glm::normalize(d);
            if (k % 6 == 0) r.ignorePrim = pi;
        } else {
            r.o = randomIn(rng, lo - 0.2f * ext, hi + 0.2f * ext);
            r.d = randomUnit(rng);
        }
        if (k % 5 == 0) r.tMax = glm::length(ext) * rng.uniform();
        rays.push_back(r);
    }
    return rays;
}

int compareAll(const Scene& s, const std::vector<Ray>& rays) {
    int bad = 0, reported = 0;
    for (const Ray& r : rays) bad += compareRay(s, r, reported);
    return bad;
}

std::vector<Triangle> randomSoup(int n, float size, Rng& rng) {
    std::vector<Triangle> tris;
    for (int i = 0; i < n; ++i) {
        const Vec3 c = randomIn(rng, Vec3(-10), Vec3(10));
        tris.push_back({c + size * randomUnit(rng), c + size * randomUnit(rng), c + size * randomUnit(rng)});
    }
    return tris;
}

// Every wide node's child box holds that child's boxes (inner) or its primitives' boxes (leaf);
// unused slots are empty leaves with a box no ray reaches; every node but the root is the child
// of exactly one slot; every primitive is in exactly one leaf (order() is a permutation).
void checkStructure(const Scene& s) {
    const BVH& bvh = s.bvh;
    std::vector<uint32_t> seen(s.prims.size(), 0), parents(bvh.nodes().size(), 0);
    auto contains = [](const AABB& outer, const AABB& inner) {
        return glm::all(glm::lessThanEqual(outer.lo, inner.lo)) && glm::all(glm::greaterThanEqual(outer.hi, inner.hi));
    };
    int badBoxes = 0, badSlots = 0;
    for (const WideNode& n : bvh.nodes()) {
        for (int k = 0; k < WideNode::kWidth; ++k) {
            const AABB box = n.box(k);
            if (n.slot[k].count == WideNode::kInner) {
                if (n.slot[k].child == 0 || n.slot[k].child >= bvh.nodes().size()) {
                    ++badSlots;
                    continue;
                }
                ++parents[n.slot[k].child];
                const WideNode& c = bvh.nodes()[n.slot[k].child];
                for (int j = 0; j < WideNode::kWidth; ++j)
                    if (!(c.slot[j].count == 0 && c.corner[0][0][j] == kInf)) badBoxes += !contains(box, c.box(j));
            } else if (n.slot[k].count == 0) {
                badSlots += !(box.lo == Vec3(kInf) && box.hi == Vec3(kInf));
            } else {
                for (uint32_t i = n.slot[k].child; i < n.slot[k].child + n.slot[k].count; ++i) {
                    const uint32_t p = bvh.order()[i];
                    ++seen[p];
                    const Primitive& pr = s.prims[p];
                    badBoxes += !contains(box, pr.shape == ShapeKind::Triangle ? s.triangles[pr.index].bounds()
                                                                               : s.spheres[pr.index].bounds());
                }
            }
        }
    }
    CHECK_MESSAGE(badBoxes == 0, "expected every child box to hold its contents, got " << badBoxes << " that do not");
    CHECK_MESSAGE(badSlots == 0, "expected valid child links and unreachable unused slots, got " << badSlots << " bad");
    int wrongParents = 0;
    for (size_t i = 1; i < parents.size(); ++i) wrongParents += parents[i] != 1;
    CHECK_MESSAGE(wrongParents == 0, "expected every node but the root to have one parent, got " << wrongParents);
    int wrongCount = 0;
    for (uint32_t c : seen) wrongCount += c != 1;
    CHECK_MESSAGE(wrongCount == 0,
                  "expected each primitive in exactly one leaf, got " << wrongCount << " that are not");
    CHECK(bvh.depth() <= BVH::kMaxDepth);
}

}  // namespace

TEST_CASE("bvh: closest and any hit equal brute force on random triangle soups") {
    Rng rng(testseed::seed(101));
    for (int n : {1, 2, 10, 1000, 20000}) {
        const Scene s = makeScene(randomSoup(n, n > 100 ? 0.5f : 3.0f, rng), {});
        INFO("soup of " << n << " triangles");
        checkStructure(s);
        const int bad = compareAll(s, makeRays(s, n >= 20000 ? 1500 : 4000, rng));
        CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
    }
}

TEST_CASE("bvh: identical, overlapping and centroid-sharing triangles") {
    Rng rng(testseed::seed(202));
    SUBCASE("500 copies of one triangle plus 500 overlapping ones") {
        std::vector<Triangle> tris(500, Triangle{Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 1, 0)});
        for (int i = 0; i < 500; ++i) {  // the same plane, shifted in it
            const Vec3 o{0.1f * rng.uniform(), 0.1f * rng.uniform(), 0.0f};
            tris.push_back({Vec3(-1, -1, 0) + o, Vec3(1, -1, 0) + o, Vec3(0, 1, 0) + o});
        }
        const Scene s = makeScene(tris, {});
        checkStructure(s);
        const int bad = compareAll(s, makeRays(s, 3000, rng));
        CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
    }
    SUBCASE("3000 triangles of different shapes whose centroids all coincide") {
        std::vector<Triangle> tris;
        const Vec3 c(1.5f, -2.0f, 0.25f);
        for (int i = 0; i < 3000; ++i) {
            const Vec3 da = randomUnit(rng);
            const Vec3 a = da * (0.1f + 3.0f * rng.uniform());
            const Vec3 db = randomUnit(rng);
            const Vec3 b = db * (0.1f + 3.0f * rng.uniform());
            tris.push_back({c + a, c + b, c - a - b});  // centroid exactly c (up to rounding)
        }
        const Scene s = makeScene(tris, {});
        checkStructure(s);
        const int bad = compareAll(s, makeRays(s, 2000, rng));
        CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
    }
    SUBCASE("exponentially spaced triangles (a deep, unbalanced tree)") {
        std::vector<Triangle> tris;
        for (int i = 0; i < 600; ++i) {
            const float x = std::pow(1.12f, static_cast<float>(i)) - 1.0f, h = 0.05f * (x + 1.0f);
            tris.push_back({Vec3(x, -h, -h), Vec3(x, h, -h), Vec3(x + h, 0, h)});
        }
        const Scene s = makeScene(tris, {});
        checkStructure(s);
        std::vector<Ray> rays;
        for (int k = 0; k < 2000; ++k) {  // rays along the row, from random starts, both ways
            const float x0 = std::pow(1.12f, 600.0f * rng.uniform()) - 1.0f;
            const Vec3 d = glm::normalize(
                Vec3{k % 2 ? 1.0f : -1.0f, 0.001f * (rng.uniform() - 0.5f), 0.001f * (rng.uniform() - 0.5f)});
            rays.emplace_back(Vec3(x0, 0.01f * (rng.uniform() - 0.5f), 0.0f), d);
        }
        const int bad = compareAll(s, rays);
        CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
    }
}

TEST_CASE("bvh: axis-parallel rays, including rays in the planes of the boxes") {
    // A grid of axis-aligned triangles with integer coordinates; rays along the axes (and along
    // face diagonals, one zero component) starting at integer and half-integer coordinates, so
    // many rays lie exactly in a box's bounding plane (0 * inf = NaN in the slab test).
    std::vector<Triangle> tris;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
            const float x = float(i), y = float(j);
            tris.push_back({Vec3(x, y, 0), Vec3(x + 1, y, 0), Vec3(x, y + 1, 0)});  // in z = 0
            tris.push_back({Vec3(x, 0, y), Vec3(x, 1, y), Vec3(x, 0, y + 1)});      // in x = i
            tris.push_back({Vec3(0, x, y), Vec3(0, x, y + 1), Vec3(1, x, y)});      // in y = i
        }
    const Scene s = makeScene(tris, {});
    const Vec3 dirs[] = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1),
                         glm::normalize(Vec3(1, 1, 0)), glm::normalize(Vec3(0, -1, 1)), glm::normalize(Vec3(1, 0, -1)),
                         // -0 components: 1/d = -inf, and the ray lies in box planes.
                         Vec3(1, -0.0f, -0.0f), Vec3(-0.0f, -1, -0.0f), Vec3(-0.0f, 0.0f, 1),
                         glm::normalize(Vec3(-1, -1, -0.0f))};
    std::vector<Ray> rays;
    for (const Vec3& d : dirs)
        for (int a = -1; a <= 14; ++a)
            for (int b = -1; b <= 14; ++b)
                for (float c : {-1.0f, 0.0f, 0.5f, 3.0f, 7.0f}) {
                    const float u = 0.5f * a, v = 0.5f * b;
                    // Start "behind" the grid along d, at (u, v) in the other two coordinates.
                    Vec3 o = d.x != 0   ? Vec3(c - 4.0f * d.x, u, v)
                             : d.y != 0 ? Vec3(u, c - 4.0f * d.y, v)
                                        : Vec3(u, v, c - 4.0f * d.z);
                    rays.emplace_back(o, d);
                }
    int hits = 0;
    for (const Ray& r : rays) {
        Ray rr = r;
        SurfacePoint sp;
        hits += s.intersect(rr, sp);
    }
    CHECK(hits > 1000);  // the test is about rays that do hit
    const int bad = compareAll(s, rays);
    CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
}

TEST_CASE("bvh: triangles mixed with spheres equal brute force") {
    Rng rng(testseed::seed(303));
    std::vector<Triangle> tris = randomSoup(2000, 1.0f, rng);
    std::vector<Sphere> spheres;
    for (int i = 0; i < 300; ++i) spheres.push_back({randomIn(rng, Vec3(-10), Vec3(10)), 0.05f + 1.5f * rng.uniform()});
    spheres.push_back({Vec3(0), 4.0f});  // a big one around many triangles: rays start inside it
    const Scene s = makeScene(tris, spheres);
    checkStructure(s);
    const int bad = compareAll(s, makeRays(s, 6000, rng));
    CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
}

TEST_CASE("bvh: an empty scene has an empty BVH and nothing is hit") {
    const Scene s = makeScene({}, {});
    CHECK(s.bvh.nodes().empty());
    CHECK(s.bvh.bounds().empty());
    CHECK(s.bvh.depth() == 0);
    Ray r(Vec3(0), Vec3(0, 0, 1));
    SurfacePoint sp;
    CHECK_FALSE(s.intersect(r, sp));
    CHECK(r.tMax == kInf);
    CHECK_FALSE(s.occluded(r));
    // And a BVH built directly over no boxes.
    BVH bvh;
    bvh.build({});
    Ray r2(Vec3(0), Vec3(1, 0, 0));
    CHECK_FALSE(bvh.traverse(r2, false, [](uint32_t, Ray&) { return true; }));
}

TEST_CASE("bvh: intersect reports the hit point, normal and material of the closest primitive") {
    // Two parallel squares at z = 1 and z = 2 and a sphere at z = 5: a ray up the z axis hits
    // z = 1 first, at p = (0.25, 0.25, 1) with the winding normal (0, 0, -1).
    std::vector<Triangle> tris = {{Vec3(-1, -1, 1), Vec3(-1, 1, 1), Vec3(1, 1, 1)},
                                  {Vec3(-1, -1, 1), Vec3(1, 1, 1), Vec3(1, -1, 1)},
                                  {Vec3(-1, -1, 2), Vec3(1, -1, 2), Vec3(1, 1, 2)},
                                  {Vec3(-1, -1, 2), Vec3(1, 1, 2), Vec3(-1, 1, 2)}};
    const Scene s = makeScene(tris, {Sphere{Vec3(0, 0, 5), 1.0f}});
    Ray r(Vec3(0.25f, 0.25f, -3), Vec3(0, 0, 1));
    SurfacePoint sp;
    REQUIRE(s.intersect(r, sp));
    CHECK_MESSAGE(r.tMax == 4.0f, "t: expected 4, got " << r.tMax);
    CHECK(sp.p.x == doctest::Approx(0.25f));
    CHECK(sp.p.z == doctest::Approx(1.0f));
    CHECK_MESSAGE(sp.n.z == doctest::Approx(-1.0f), "normal z: expected -1, got " << sp.n.z);
    CHECK((sp.prim == 0 || sp.prim == 1));  // (0.25, 0.25) lies on their shared diagonal
    CHECK(sp.material == 0);
    // Ignoring that triangle, the ray passes through the shared diagonal and must still hit
    // the first square via the other triangle (the point is on their shared edge).
    Ray r2(Vec3(0.25f, 0.25f, -3), Vec3(0, 0, 1), kInf, sp.prim);
    SurfacePoint sp2;
    REQUIRE(s.intersect(r2, sp2));
    CHECK_MESSAGE(r2.tMax == 4.0f, "t with the first triangle ignored: expected 4 (its neighbour), got " << r2.tMax);
    // Off the diagonal: only one triangle; ignoring it reaches z = 2.
    Ray r3(Vec3(0.5f, -0.25f, -3), Vec3(0, 0, 1));
    REQUIRE(s.intersect(r3, sp));
    Ray r4(Vec3(0.5f, -0.25f, -3), Vec3(0, 0, 1), kInf, sp.prim);
    REQUIRE(s.intersect(r4, sp2));
    CHECK_MESSAGE(r4.tMax == 5.0f, "expected the second square at t = 5, got " << r4.tMax);
    // From between the squares and the sphere: the sphere's near side at z = 4, t = 1.5.
    Ray r5(Vec3(0, 0, 2.5f), Vec3(0, 0, 1));
    REQUIRE(s.intersect(r5, sp));
    CHECK_MESSAGE(r5.tMax == doctest::Approx(1.5f), "sphere: expected t = 1.5, got " << r5.tMax);
    CHECK(sp.n.z == doctest::Approx(-1.0f));
}

TEST_CASE("bvh: degenerate triangles, axis-parallel rays and origins inside the boxes") {
    Rng rng(testseed::seed(404));
    std::vector<Triangle> tris = randomSoup(2000, 0.7f, rng);
    for (int i = 0; i < 2000; i += 5) tris[i].p2 = tris[i].p1;                        // two equal corners
    for (int i = 1; i < 2000; i += 7) tris[i].p2 = 0.5f * (tris[i].p0 + tris[i].p1);  // collinear
    for (int i = 2; i < 2000; i += 11) tris[i].p1 = tris[i].p2 = tris[i].p0;          // a point
    for (int i = 3; i < 2000; i += 13) tris[i].p1.z = tris[i].p2.z = tris[i].p0.z;    // axis-aligned
    const Scene s = makeScene(tris, {});
    checkStructure(s);
    std::vector<Ray> rays = makeRays(s, 1000, rng);
    const Vec3 axes[] = {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)};
    for (int k = 0; k < 2000; ++k) {
        // From inside the scene's boxes: a corner of some triangle (so on a leaf box's planes)
        // or a random point, along an axis (with +0 or -0 in the other components) or anywhere.
        const Triangle& t = tris[rng.nextU32() % tris.size()];
        const Vec3 o = k % 2 ? t.p0 : randomIn(rng, s.bounds.lo, s.bounds.hi);
        Vec3 d = k % 3 ? axes[k % 6] : randomUnit(rng);
        if (k % 4 == 0) d = Vec3(d.x == 0.0f ? -0.0f : d.x, d.y == 0.0f ? -0.0f : d.y, d.z == 0.0f ? -0.0f : d.z);
        rays.emplace_back(o, d);
    }
    const int bad = compareAll(s, rays);
    CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
}

TEST_CASE("bvh: one triangle is a root with one leaf") {
    const Scene s = makeScene({{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)}}, {});
    checkStructure(s);
    REQUIRE(s.bvh.nodes().size() == 1);
    CHECK(s.bvh.depth() == 1);
    CHECK(s.bvh.nodes()[0].slot[0].count == 1);
    for (int k = 1; k < WideNode::kWidth; ++k) CHECK(s.bvh.nodes()[0].slot[k].count == 0);
    Rng rng(testseed::seed(505));
    std::vector<Ray> rays = makeRays(s, 2000, rng);
    for (float x : {-0.5f, 0.0f, 0.25f, 0.5f, 1.0f}) {  // through corners and edges, both ways
        rays.emplace_back(Vec3(x, 0.0f, -1.0f), Vec3(0, 0, 1));
        rays.emplace_back(Vec3(0.0f, x, 1.0f), Vec3(0, 0, -1));
        rays.emplace_back(Vec3(x, 1.0f - x, -1.0f), Vec3(0, 0, 1));
    }
    const int bad = compareAll(s, rays);
    CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
}

TEST_CASE("bvh: huge and tiny scales, and far from the origin") {
    Rng rng(testseed::seed(606));
    const std::vector<Triangle> soup = randomSoup(1000, 0.6f, rng);
    for (const std::pair<float, float>& scaleShift :
         {std::pair{1e-12f, 0.0f}, std::pair{1e-4f, 0.0f}, std::pair{1e4f, 0.0f}, std::pair{1e12f, 0.0f},
          std::pair{1.0f, 1e5f}}) {
        const float scale = scaleShift.first, shift = scaleShift.second;  // named, not bound (clang < 16, lambdas)
        std::vector<Triangle> tris = soup;
        for (Triangle& t : tris)
            for (Vec3* p : {&t.p0, &t.p1, &t.p2}) *p = *p * scale + Vec3(shift);
        const Scene s = makeScene(tris, {});
        INFO("scale " << scale << ", moved by " << shift);
        checkStructure(s);
        const int bad = compareAll(s, makeRays(s, 1000, rng));
        CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
    }
}

// Rays aimed exactly at the vertices and edges of a bumpy grid, and a float step beside them,
// from near and far, at tiny and huge scales and far from the origin: where a ray meets two
// triangles of different leaves at one point, the nearer hit's box entry, rounded, may lie a
// float step beyond the hit already found (a box left out there loses the closer hit by 1 ulp).
TEST_CASE("bvh: rays through the vertices and edges of a mesh equal brute force, near and far") {
    Rng rng(testseed::seed(808));
    const int n = 24;  // n x n quads, two triangles each
    std::vector<Vec3> v;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) v.push_back(Vec3(float(i) / n, float(j) / n, 0.02f * rng.uniform()));
    std::vector<Triangle> grid;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const Vec3 &a = v[size_t(j * (n + 1) + i)], &b = v[size_t(j * (n + 1) + i + 1)];
            const Vec3 &c = v[size_t((j + 1) * (n + 1) + i)], &d = v[size_t((j + 1) * (n + 1) + i + 1)];
            grid.push_back({a, b, d});
            grid.push_back({a, d, c});
        }
    for (const std::pair<float, float>& scaleShift :
         {std::pair{1.0f, 0.0f}, std::pair{1e-18f, 0.0f}, std::pair{1e15f, 0.0f}, std::pair{1.0f, 1e3f}}) {
        const float scale = scaleShift.first, shift = scaleShift.second;
        std::vector<Triangle> tris = grid;
        for (Triangle& t : tris)
            for (Vec3* p : {&t.p0, &t.p1, &t.p2}) *p = *p * scale + Vec3(shift);
        const Scene s = makeScene(tris, {});
        std::vector<Ray> rays;
        for (int k = 0; k < 2000; ++k) {
            const Triangle& t = tris[rng.nextU32() % tris.size()];
            const Vec3 a = k % 3 == 0 ? t.p0 : k % 3 == 1 ? t.p1 : t.p2, b = k % 3 == 0 ? t.p1 : t.p2;
            Vec3 target = k % 4 == 0 ? a : a + (k % 4 == 1 ? 0.5f : rng.uniform()) * (b - a);
            if (k % 5 == 0) target.x = std::nextafter(target.x, k % 2 ? kInf : -kInf);
            const float dist = (k % 2 ? 3.0f : 3e3f) * scale;  // near, and far: a grid a few pixels wide
            const Vec3 o = target + dist * Vec3(rng.uniform() - 0.5f, rng.uniform() - 0.5f, 1.0f);
            rays.push_back(Ray(o, glm::normalize(target - o), k % 7 == 0 ? 1.5f * dist : kInf));
        }
        INFO("scale " << scale << ", moved by " << shift);
        const int bad = compareAll(s, rays);
        CHECK_MESSAGE(bad == 0, "expected 0 disagreements with brute force, got " << bad);
    }
}

TEST_CASE("bvh: traverse visits each leaf item at most once, nearest box first") {
    // A row of 64 unit squares along +x, a ray along the row: the items come in order of
    // distance, each once, and the first hit ends an any-hit traversal.
    std::vector<AABB> boxes;
    for (int i = 0; i < 64; ++i) {
        AABB b;
        b.expand(Vec3(float(i), -0.5f, -0.5f));
        b.expand(Vec3(float(i) + 0.5f, 0.5f, 0.5f));
        boxes.push_back(b);
    }
    std::reverse(boxes.begin(), boxes.end());  // primitive i sits at x = 63 - i
    BVH bvh;
    bvh.build(boxes);
    Ray ray(Vec3(-1, 0.1f, 0.2f), Vec3(1, 0, 0));
    std::vector<uint32_t> visited;
    bvh.traverse(ray, false, [&](uint32_t item, Ray&) {
        visited.push_back(bvh.order()[item]);
        return false;
    });
    std::vector<uint32_t> sorted = visited;
    std::sort(sorted.begin(), sorted.end());
    CHECK_MESSAGE(std::unique(sorted.begin(), sorted.end()) == sorted.end(), "an item was visited twice");
    CHECK(visited.size() == 64);
    // A leaf holds up to kMaxWideLeafSize items in any order, but leaf by leaf the row is walked
    // from x = 0 on: items that far apart in the visit are in different leaves.
    const size_t gap = BVH::kMaxWideLeafSize;
    int outOfOrder = 0;
    for (size_t i = gap; i < visited.size(); ++i) outOfOrder += 63 - int(visited[i]) < 63 - int(visited[i - gap]);
    CHECK_MESSAGE(outOfOrder == 0, "expected the nearest boxes first, got " << outOfOrder << " items out of order");
    int calls = 0;
    CHECK(bvh.traverse(ray, true, [&](uint32_t, Ray&) { return ++calls > 0; }));
    CHECK(calls == 1);
}

TEST_CASE("bvh: the AVX2 copy and the baseline copy of intersect and occluded give the same bits") {
    // Scene::intersect and occluded run a copy of their code compiled for AVX2 when the CPU has
    // it, else the x86-64 baseline copy (scene.cpp). Images must not depend on which: every bit
    // of every result must agree. (The ctest entry framework-bvh-baseline runs the brute-force
    // tests above with the baseline copy: PATHSPACE_NO_AVX2=1.)
    const bool before = std::getenv("PATHSPACE_NO_AVX2") == nullptr;
    if (!useAvx2Tracing(true)) {
        MESSAGE("no AVX2 copy on this build or CPU: one copy only, nothing to compare");
        return;
    }
    Rng rng(testseed::seed(404));
    std::vector<Sphere> spheres;
    for (int i = 0; i < 100; ++i) spheres.push_back({randomIn(rng, Vec3(-10), Vec3(10)), 0.05f + 1.5f * rng.uniform()});
    const Scene s = makeScene(randomSoup(20000, 0.5f, rng), spheres);
    const std::vector<Ray> rays = makeRays(s, 20000, rng);
    auto bits = [](float f) {
        uint32_t u;
        std::memcpy(&u, &f, sizeof u);
        return u;
    };
    auto trace = [&](bool avx2) {
        useAvx2Tracing(avx2);
        std::vector<uint32_t> out;  // per ray: hit, t, p, n, prim, occluded
        for (const Ray& ray : rays) {
            Ray r = ray;
            SurfacePoint sp;
            out.push_back(s.intersect(r, sp));
            for (float f : {r.tMax, sp.p.x, sp.p.y, sp.p.z, sp.n.x, sp.n.y, sp.n.z}) out.push_back(bits(f));
            out.push_back(sp.prim);
            out.push_back(s.occluded(ray));
        }
        return out;
    };
    const std::vector<uint32_t> avx2 = trace(true), baseline = trace(false);
    useAvx2Tracing(before);
    size_t differ = 0;
    for (size_t i = 0; i < avx2.size(); ++i) differ += avx2[i] != baseline[i];
    CHECK_MESSAGE(differ == 0, "expected the AVX2 and the baseline copy to give the same bits, got "
                                   << differ << " of " << avx2.size() << " numbers different");
}

TEST_CASE("bvh: large arrays start on 2 MB boundaries, small ones on cache lines") {
    // LargePageAllocator (framework/large_pages.h): the BVH's nodes and the scene's leaf-ordered
    // triangles, when 2 MB or more, start on a 2 MB boundary (so that 2 MB pages can back them);
    // smaller arrays on a 64-byte cache line. Contents survive the vector's growth.
    auto address = [](const void* p) { return reinterpret_cast<uintptr_t>(p); };
    std::vector<int, LargePageAllocator<int>> small(100), large;
    CHECK(address(small.data()) % 64 == 0);
    for (int i = 0; i < (3 << 20) / int(sizeof(int)); ++i) large.push_back(i);  // grows past 2 MB
    CHECK_MESSAGE(address(large.data()) % (2u << 20) == 0, "expected a 3 MB array on a 2 MB boundary");
    bool intact = true;
    for (int i = 0; i < int(large.size()); ++i) intact &= large[size_t(i)] == i;
    CHECK(intact);
    Rng rng(testseed::seed(505));
    const Scene s = makeScene(randomSoup(250000, 0.05f, rng), {});
    REQUIRE(s.bvh.nodes().size() * sizeof(WideNode) >= (2u << 20));
    CHECK(address(s.bvh.nodes().data()) % (2u << 20) == 0);
}
