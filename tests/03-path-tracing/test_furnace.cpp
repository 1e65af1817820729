// Lesson 3, graded: the closed furnace (Eq. 3.8). The camera sits inside a closed enclosure
// whose walls emit Le and reflect diffusely with albedo a; every ray sees
// L = Le (1 - a^(D+1)) / (1 - a) with at most D bounces: the Neumann series truncated at D
// (Eq. 3.2, 3.3). The statistical tests use the sphere furnace (data/furnace-sphere.scene): in
// the cube of scenes/furnace.scene next-event estimation has infinite variance (README 1.6),
// and a t-test needs a finite one. The exact tests use the cube. The tests compare
// with the TRUNCATED value, with a power check (standard error <= 0.35 % of L): the depths are
// chosen so that one bounce more or less changes L by 1.6 % (a = 0.5, D = 5), 2.3 % (a = 0.8,
// D = 10), 2.8 % (a = 0.99, D = 30) and 4.8 % (a = 1, D = 20), 4.6 standard errors or more even
// at the bound. Next-event estimation's standard error is heavy-tailed here: over
// PATHSPACE_TEST_SEED 0-39 at a = 0.5 its mean is 0.071 % of L and its largest 0.29 % (the other
// estimators': 0.10-0.18 %, steady); the bound was 0.2 % and failed at 2 of 41 seeds (seeds.sh).
#include "lesson03.h"

using namespace lesson03;

namespace {

struct FurnaceCase {
    float albedo;
    int D;
    int samples;  // enough for the power check with every estimator
};
constexpr FurnaceCase kCases[] = {{0.5f, 5, 50000}, {0.8f, 10, 120000}, {0.99f, 30, 60000}};

void checkFurnace(const Estimator& e, uint64_t seed) {
    for (const FurnaceCase& c : kCases) {
        const int samples = c.samples;
        const ps::Scene scene = furnace(Enclosure::Sphere, c.albedo, 1.0f);
        const double expected = 3.0 * furnaceRadiance(c.albedo, 1.0, c.D);
        const Samples s = sampleLi(scene, e, c.D, samples, seed++);
        CHECK_MESSAGE(s.bad == 0, e.name << ", closed furnace albedo " << c.albedo
                                         << ": expected 0 NaN or Inf samples, got " << s.bad);
        const ps::stats::TTestResult t = ps::stats::tTest(s.w, expected, alpha(), 0.0035);
        CHECK_MESSAGE(t.passed, e.name << ", sphere furnace (albedo " << c.albedo << ", Le 1, maxdepth " << c.D << "), "
                                       << samples << " rays: expected L = (1 - a^(D+1)) / (1 - a) = " << expected / 3.0
                                       << " per channel (R + G + B = " << expected << "), got R + G + B = " << t.mean
                                       << " +- " << t.stdError << "\n  " << t.report);
    }
}

}  // namespace

TEST_CASE("path tracing: closed furnace with albedo 0.5, 0.8 and 0.99, BSDF sampling only (t-test) [2 pts]") {
    checkFurnace(estimators()[0], 311);
}

TEST_CASE("path tracing: closed furnace with albedo 0.5, 0.8 and 0.99, next-event estimation (t-test) [2 pts]") {
    checkFurnace(estimators()[1], 321);
}

TEST_CASE("path tracing: closed furnace with albedo 0.5, 0.8 and 0.99, MIS (t-test) [2 pts]") {
    checkFurnace(estimators()[2], 331);
}

TEST_CASE("path tracing: closed furnace with albedo 1 terminates and returns (D + 1) Le [1 pt]") {
    // Nothing is absorbed, so Russian roulette never ends a path (the throughput stays 1): only
    // the maximum depth D = 20 does. The random walk returns exactly (D + 1) Le for every
    // sample; the other two return it on average (their light samples are random).
    constexpr int D = 20;
    const ps::Scene cube = furnace(Enclosure::Cube, 1.0f, 1.0f), sphere = furnace(Enclosure::Sphere, 1.0f, 1.0f);
    const double expected = 3.0 * (D + 1);
    const Samples walk = sampleLi(cube, estimators()[0], D, 2000, 341);
    CHECK_MESSAGE((walk.bad == 0 && walk.w.n == 2000 && walk.min == expected && walk.max == expected),
                  "pt-bsdf (LiRandomWalk), closed cube furnace (albedo 1, Le 1, maxdepth "
                      << D << "): expected every sample to be "
                      << "exactly (D + 1) Le = " << D + 1 << " per channel (R + G + B = " << expected
                      << "), got R + G + B from " << walk.min << " to " << walk.max << " (" << walk.bad
                      << " NaN or Inf)");
    uint64_t seed = 342;
    for (const Estimator& e : {estimators()[1], estimators()[2]}) {
        const Samples s = sampleLi(sphere, e, D, 20000, seed++);
        CHECK_MESSAGE(s.bad == 0, e.name << ", closed furnace albedo 1: expected 0 NaN or Inf samples, got " << s.bad);
        const ps::stats::TTestResult t = ps::stats::tTest(s.w, expected, alpha(), 0.0035);
        CHECK_MESSAGE(t.passed, e.name << ", sphere furnace (albedo 1, Le 1, maxdepth " << D
                                       << "): expected (D + 1) Le = " << D + 1
                                       << " per channel (R + G + B = " << expected << "), got R + G + B = " << t.mean
                                       << " +- " << t.stdError << "\n  " << t.report);
    }
}

TEST_CASE("path tracing: closed furnace with albedo 0 returns exactly Le [1 pt]") {
    // A black surface reflects nothing: every sample of every estimator is exactly the emission
    // seen directly, Le = (0.25, 0.25, 0.25) here, whatever the maximum depth.
    const ps::Scene scene = furnace(Enclosure::Cube, 0.0f, 0.25f);
    for (const Estimator& e : estimators()) {
        const Samples s = sampleLi(scene, e, 8, 500, 351);
        CHECK_MESSAGE(
            (s.bad == 0 && s.w.n == 500 && s.min == 0.75 && s.max == 0.75),
            e.name << ", closed cube furnace (albedo 0, Le 0.25, maxdepth 8): expected every sample to be exactly Le "
                   << "(R + G + B = 0.75), got R + G + B from " << s.min << " to " << s.max << " (" << s.bad
                   << " NaN or Inf)");
    }
}
