// Lesson 0, graded: the triangle test at scales 1e-4, 1 and 1e4. A float test without absolute
// epsilons works the same at every scale: hit distances are accurate relative to the scene, and a
// ray leaving a surface from a point moved off it by offsetRayOrigin (framework/ray.h) does not
// hit the surface again.
#include <doctest/doctest.h>
#include <cmath>
#include "lesson00.h"
#include "seed.h"

using namespace lesson00;

namespace {

// A random triangle with corners in scale * [-1, 1]^3, not a sliver.
Triangle randomTriangle(float scale, ps::Rng& rng) {
    Triangle t;
    do {
        for (Vec3* p : {&t.p0, &t.p1, &t.p2})
            *p = scale * (2.0f * Vec3{rng.uniform(), rng.uniform(), rng.uniform()} - 1.0f);
    } while (t.area() < 0.05f * scale * scale);
    return t;
}

}  // namespace

TEST_CASE("rays: hit distances have relative error below 1e-5 at scales 1e-4 and 1 and 1e4 [1 pt]") {
    // Rays from 1 to 5 scale units away, |cos| >= 0.2, both sides, aimed at interior points; the
    // exact t of the float ray and the float triangle is computed in double.
    ps::Rng rng(ps::testseed::seed(12));
    for (float scale : {1e-4f, 1.0f, 1e4f}) {
        int failures = 0, rays = 0;
        for (int k = 0; k < 50; ++k) {
            const Triangle tri = randomTriangle(scale, rng);
            for (int i = 0; i < 100; ++i) {
                const float e1 = 0.01f + 0.98f * rng.uniform(), e2 = (1.0f - e1) * (0.01f + 0.98f * rng.uniform());
                const Vec3 d =
                    directionWithCos(tri.normal(), (i % 2 ? 1.0f : -1.0f) * (0.2f + 0.8f * rng.uniform()), rng);
                const Ray ray(pointAt(tri, e1, e2) + scale * (1.0f + 4.0f * rng.uniform()) * d, -d);
                const double t = exactT(ray, tri);
                const Hit h = intersect(ray, tri);
                ++rays;
                const double err = h.hit ? std::abs(h.t - t) / t : 1.0;
                if (err >= 1e-5 && ++failures <= 3)
                    FAIL_CHECK("scale " << scale << ": " << str(ray) << "\n  " << str(tri)
                                        << "\n  expected a hit at t = " << t << " (relative error < 1e-5), got "
                                        << str(h)
                                        << (h.hit ? " (relative error " + std::to_string(err) + ")" : std::string()));
            }
        }
        CHECK_MESSAGE(failures == 0, "scale " << scale << ": expected all " << rays << " hits accurate to 1e-5, got "
                                              << failures << " wrong or missing");
    }
}

TEST_CASE(
    "rays: a ray leaving a triangle from an offset origin does not hit it again at scales 1e-4 and 1 and 1e4 [1 pt]") {
    // As a renderer does it: a ray hits the triangle; the hit point is computed from the reported
    // barycentrics; a new ray leaves it from offsetRayOrigin(p, n, errScale, w) in a direction w
    // on either side (reflection or transmission), half of them grazing (|cos| = 1e-3). The new
    // ray must not hit the triangle it leaves (the test does not use Ray::ignorePrim).
    ps::Rng rng(ps::testseed::seed(13));
    for (float scale : {1e-4f, 1.0f, 1e4f}) {
        int rehits = 0, misses = 0, trials = 0;
        for (int k = 0; k < 50; ++k) {
            const Triangle tri = randomTriangle(scale, rng);
            const Vec3 n = tri.normal();
            for (int i = 0; i < 200; ++i) {
                const float e1 = 0.01f + 0.98f * rng.uniform(), e2 = (1.0f - e1) * (0.01f + 0.98f * rng.uniform());
                const Vec3 din = directionWithCos(n, (i % 2 ? 1.0f : -1.0f) * (0.05f + 0.95f * rng.uniform()), rng);
                const Ray in(pointAt(tri, e1, e2) + 3.0f * scale * din, -din);
                ++trials;
                const Hit first = intersect(in, tri);
                if (!first.hit) {
                    if (++misses <= 3)
                        FAIL_CHECK("scale " << scale << ": the incoming ray missed (expected a hit at t = "
                                            << exactT(in, tri) << ")\n  " << str(in) << "\n  " << str(tri));
                    continue;
                }
                const Vec3 p = pointAt(tri, first.b1, first.b2);
                const float c = (i % 4 < 2 ? 1e-3f : 0.01f + 0.99f * rng.uniform()) * (i % 3 ? 1.0f : -1.0f);
                const Vec3 w = directionWithCos(n, c, rng);
                const Ray out(ps::offsetRayOrigin(p, n, tri.errScale(), w), w);
                const Hit again = intersect(out, tri);
                if (again.hit && ++rehits <= 3)
                    FAIL_CHECK("scale " << scale << ": a ray leaving the triangle (cos to the normal " << c
                                        << ") hit it again: " << str(again) << " (expected no hit)\n  " << str(out)
                                        << "\n  " << str(tri) << "\n  it left the point " << str(p) << " of "
                                        << str(first));
            }
        }
        CHECK_MESSAGE(misses == 0, "scale " << scale << ": expected all " << trials << " incoming rays to hit, got "
                                            << misses << " misses");
        CHECK_MESSAGE(rehits == 0, "scale " << scale << ": expected 0 of " << trials - misses
                                            << " leaving rays to re-hit their triangle, got " << rehits);
    }
}
