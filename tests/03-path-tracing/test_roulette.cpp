// Lesson 3, graded: Russian roulette's survival probability (Eq. 3.5) and the meaning of the
// maximum depth (Eq. 3.3). Exact checks.
#include "lesson03.h"

using namespace lesson03;

TEST_CASE("roulette: survival probability from the path throughput, bounded below, after 3 bounces (Eq. 3.5) [1 pt]") {
    struct Case {
        Color beta;
        int bounces;
        float expected;
    };
    const Case cases[] = {
        {Color(0.5f, 0.2f, 0.1f), 0, 1.0f},
        {Color(1e-3f), 1, 1.0f},
        {Color(0.0f), 2, 1.0f},
        {Color(0.5f, 0.2f, 0.1f), 3, 0.5f},
        {Color(0.1f, 0.7f, 0.3f), 10, 0.7f},
        {Color(2.0f, 0.0f, 0.0f), 4, 1.0f},
        {Color(1e-3f, 0.02f, 0.0f), 5, 0.05f},
        {Color(0.0f), 7, 0.05f},
        {Color(0.05f), 3, 0.05f},
    };
    for (const Case& c : cases) {
        const float q = ps::survivalProbability(c.beta, c.bounces);
        CHECK_MESSAGE(q == doctest::Approx(c.expected).epsilon(1e-6),
                      "survivalProbability(beta " << str(c.beta) << ", after " << c.bounces << " bounces): expected "
                                                  << c.expected << ", got " << q);
    }
}

TEST_CASE("path tracing: maxdepth 0 is the emission seen directly, 1 and 2 add one and two bounces (Eq. 3.3) [1 pt]") {
    // In the closed furnace (albedo 0.5, Le = 1) every path sees emission Le at every vertex,
    // and a Lambertian BSDF sample has weight exactly the albedo: without Russian roulette
    // (bounces < 3) the random walk has no variance at all. So every single sample must be
    //   D = 0: Le (all three estimators: nothing but the emission seen directly),
    //   D = 1: Le (1 + a) = 1.5 and D = 2: Le (1 + a + a^2) = 1.75 (pt-bsdf).
    const ps::Scene scene = furnace(Enclosure::Cube, 0.5f, 1.0f);
    for (const Estimator& e : estimators()) {
        const Samples s = sampleLi(scene, e, 0, 200, 301);
        CHECK_MESSAGE(
            (s.bad == 0 && s.w.n == 200 && s.min == 3.0 && s.max == 3.0),
            e.name
                << ", closed cube furnace (albedo 0.5, Le 1), maxdepth 0: expected every sample to be exactly Le = 1 "
                << "per channel (R + G + B = 3), got R + G + B from " << s.min << " to " << s.max << " (" << s.bad
                << " NaN or Inf)");
    }
    for (int D : {1, 2}) {
        const double expected = 3.0 * furnaceRadiance(0.5, 1.0, D);
        const Samples s = sampleLi(scene, estimators()[0], D, 200, 302);
        CHECK_MESSAGE((s.bad == 0 && s.w.n == 200 && s.min == expected && s.max == expected),
                      "pt-bsdf (LiRandomWalk), closed cube furnace (albedo 0.5, Le 1), maxdepth "
                          << D << ": expected every sample to be exactly " << expected / 3.0
                          << " per channel (R + G + B = " << expected << "), got R + G + B from " << s.min << " to "
                          << s.max << " (" << s.bad << " NaN or Inf)");
    }
}

TEST_CASE("roulette: Russian roulette ends long paths (furnace, albedo 0.5, maxdepth 1000) [1 pt]") {
    // With maxdepth 1000 only Russian roulette can end a path in the closed furnace (albedo 0.5):
    // without it every path would trace 1001 rays (and NEE another 1000 shadow rays). With
    // Eq. 3.5 a path survives its first two bounces for sure and then each further one with
    // probability about 0.5 (q follows the throughput, and a survivor's throughput is divided
    // by q): a few rays per path. Counted with takeRayCount (scene.h) over 1000 paths; every
    // sample must also be at least the emission seen directly, Le = 1 per channel.
    const ps::Scene scene = furnace(Enclosure::Cube, 0.5f, 1.0f);
    for (const Estimator& e : estimators()) {
        ps::takeRayCount();
        const Samples s = sampleLi(scene, e, 1000, 1000, 361);
        const double raysPerPath = double(ps::takeRayCount()) / 1000.0;
        CHECK_MESSAGE(
            (s.bad == 0 && s.w.n == 1000 && s.min >= 3.0 && raysPerPath <= 40.0),
            e.name << ", closed cube furnace (albedo 0.5, Le 1), maxdepth 1000, 1000 paths: expected at most 40 "
                   << "rays per path (Russian roulette, Eq. 3.5) and every sample >= Le (R + G + B >= 3), got "
                   << raysPerPath << " rays per path, R + G + B from " << s.min << " to " << s.max << " (" << s.bad
                   << " NaN or Inf)");
    }
}
