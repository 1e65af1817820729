// Lesson 10, graded: the ADRRS decision at a vertex made by hand (Eq. 10.2, 10.5-10.7, 10.9): the
// pixel estimate, the path's weight, the cache looked up where the path is, and lesson 3's roulette
// where the cache knows nothing.
#include "lesson10.h"

using namespace lesson10;

namespace {

// A vertex on the closed box's floor at p, seen from straight above, with throughput beta.
ps::WalkVertex floorVertex(const Vec3& p, const Color& beta, int bounces, const Vec3& pPrev) {
    ps::WalkVertex v;
    v.hit = true;
    v.bounces = bounces;
    v.sp.p = p;
    v.sp.n = Vec3(0, 1, 0);
    v.sp.material = 0;
    v.wo = glm::normalize(pPrev - p);
    v.beta = beta;
    v.specular = false;
    v.pdfPrev = 1.0f;
    v.pPrev = pPrev;
    return v;
}

}  // namespace

TEST_CASE(
    "ADRRS decision: the pixel estimate and q from a hand-filled cache, looked up where the path is (Eq. 10.2, 10.5-10.7, 10.9) [2 pts]") {
    const ps::Scene scene = closedBox(0.5f, 8, false);
    ps::AdjointCache cache(scene.bounds, 4);
    const Vec3 prev(0.9f, 0.9f, 0.1f);
    const ps::WalkVertex base = floorVertex(Vec3(0.3f, 0.0f, 0.6f), Color(0.5f), 2, prev);
    const int here = cache.entry(base.sp.p, base.sp.n, base.wo);
    const int there = cache.entry(prev, base.sp.n, base.wo);
    REQUIRE(here != there);
    cache.set(here, Color(0.2f, 0.4f, 0.6f));  // Psi~ = 0.4 as one number
    cache.set(there, Color(10.0f));            // where the path came from: must not matter

    // I~ at the camera ray's first vertex.
    ps::WalkVertex x0 = base;
    x0.bounces = 0;
    x0.beta = Color(1.0f);
    const float I = ps::pixelEstimate(cache, scene, x0);
    CHECK_MESSAGE(std::abs(I - 0.4f) <= 1e-6f,
                  "pixelEstimate at a first vertex whose entry holds (0.2, 0.4, 0.6): "
                  "expected the mean of the channels, 0.4 (Eq. 10.9), got "
                      << I);
    ps::WalkVertex miss = x0;
    miss.hit = false;
    CHECK_MESSAGE(ps::pixelEstimate(cache, scene, miss) == -1.0f,
                  "pixelEstimate of a camera ray that misses: expected -1");
    ps::WalkVertex mirror = x0;
    mirror.sp.material = 1;
    CHECK_MESSAGE(ps::pixelEstimate(cache, scene, mirror) == -1.0f,
                  "pixelEstimate at a mirror (a delta material: nothing cached): expected -1");
    ps::WalkVertex unknown = x0;
    unknown.sp.p = Vec3(0.9f, 0.0f, 0.9f);
    CHECK_MESSAGE(ps::pixelEstimate(cache, scene, unknown) == -1.0f,
                  "pixelEstimate at an entry without a sample: expected -1");

    // q with I~ = 1.2: C_ww = 1.2 / 0.4 = 3, window [1, 5].
    struct Case {
        Color beta;
        double q;
        const char* what;
    };
    for (const Case& c :
         {Case{Color(0.5f), 0.5, "grey beta 0.5: nu = 0.5 below the window [1, 5], q = nu / 1"},
          Case{Color(1.0f, 0.5f, 0.25f), 0.55 / 1.2, "beta (1, 0.5, 0.25): nu = (0.2 + 0.2 + 0.15) / 1.2, q = nu / 1"},
          Case{Color(2.0f), 1.0, "grey beta 2: inside the window, q = 1"},
          Case{Color(8.0f), 1.6, "grey beta 8: above the window, q = nu / 5"}}) {
        ps::WalkVertex v = base;
        v.beta = c.beta;
        const float q = ps::adrrsContinuations(cache, scene, v, 1.2f);
        CHECK_MESSAGE(std::abs(q - c.q) <= 1e-6 * c.q,
                      "adrrsContinuations at a vertex whose entry holds Psi~ = (0.2, 0.4, 0.6), I~ = 1.2: expected q = "
                          << c.q << " (" << c.what << "; Eq. 10.2, 10.5-10.7), got " << q
                          << " (looked up where the path came from, where the cache holds 10, q would be above 2)");
    }

    // Where ADRRS cannot decide: no decision (lesson 3's roulette then plays after the bounce).
    ps::WalkVertex late = base;
    late.bounces = 5;
    late.beta = Color(0.3f);
    const float noPixel = ps::adrrsContinuations(cache, scene, late, -1.0f);
    CHECK_MESSAGE(noPixel == ps::kNoDecision,
                  "adrrsContinuations without a pixel estimate (I~ = -1): expected kNoDecision (lesson 3's roulette "
                  "plays), got "
                      << noPixel);
    ps::WalkVertex lateUnknown = late;
    lateUnknown.sp.p = Vec3(0.9f, 0.0f, 0.9f);
    const float noEntry = ps::adrrsContinuations(cache, scene, lateUnknown, 1.2f);
    CHECK_MESSAGE(noEntry == ps::kNoDecision,
                  "adrrsContinuations at an entry without a sample: expected kNoDecision, got " << noEntry);
    ps::WalkVertex lateMirror = late;
    lateMirror.sp.material = 1;
    const float atMirror = ps::adrrsContinuations(cache, scene, lateMirror, 1.2f);
    CHECK_MESSAGE(atMirror == ps::kNoDecision,
                  "adrrsContinuations at a mirror (delta: nothing cached): expected kNoDecision, got " << atMirror);

    // Entries the cache cannot vouch for: black (no light seen), or too noisy.
    const auto fallback = [&](const char* what) {
        const float got = ps::adrrsContinuations(cache, scene, late, 1.2f);
        CHECK_MESSAGE(got == ps::kNoDecision, "adrrsContinuations where the entry holds "
                                                  << what << " (not reliable): expected kNoDecision, got " << got);
    };
    cache.set(here, Color(0.0f));
    fallback("black");
    ps::AdjointCache noisy(scene.bounds, 4);
    noisy.add(here, Color(0.0f));
    noisy.add(here, Color(0.0f));
    noisy.add(here, Color(3.0f));  // mean 1, relative standard error 1 > kMaxRelativeError
    cache = noisy;
    fallback("the samples 0, 0, 3");
    ps::AdjointCache steady(scene.bounds, 4);
    for (const float x : {0.3f, 0.4f, 0.5f, 0.4f}) steady.add(here, Color(x));  // mean 0.4, relative error 0.102
    const float q = ps::adrrsContinuations(steady, scene, base, 1.2f);
    CHECK_MESSAGE(std::abs(q - 0.5f) <= 1e-6f,
                  "adrrsContinuations where the entry holds the samples 0.3, 0.4, 0.5, "
                  "0.4 (reliable, Psi~ = 0.4), beta 0.5, I~ = 1.2: expected q = 0.5, got "
                      << q);
}
