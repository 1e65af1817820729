// Lesson 2, graded: the MIS weights (lessons/02-direct-mis/mis.h; Eq. 2.7-2.10 of the lesson
// README) and the delta case (Eq. 2.12). Every check here is exact or deterministic.
#include <cmath>
#include "lesson02.h"
#include "seed.h"

using namespace lesson02;
using ps::Heuristic;
using ps::Technique;

namespace {

std::string name(Heuristic h) {
    return h == Heuristic::Balance ? "balance" : h == Heuristic::Power ? "power" : "maximum";
}
constexpr Heuristic kHeuristics[] = {Heuristic::Balance, Heuristic::Power, Heuristic::Maximum};

std::string describe(const std::vector<Technique>& t) {
    std::ostringstream s;
    s.precision(9);
    for (size_t k = 0; k < t.size(); ++k) s << (k ? ", " : "") << "(n " << t[k].n << ", pdf " << t[k].pdf << ")";
    return s.str();
}

// Eq. 2.7-2.9 in double (no overflow for the pdfs used with it).
double expectedWeight(Heuristic h, int i, const std::vector<Technique>& t) {
    std::vector<double> q;
    for (const Technique& k : t) q.push_back(double(k.n) * double(k.pdf));
    if (!(q[i] > 0.0)) return 0.0;
    if (h == Heuristic::Maximum) {
        int first = 0;
        for (int k = 1; k < int(q.size()); ++k)
            if (q[k] > q[first]) first = k;
        return i == first ? 1.0 : 0.0;
    }
    double sum = 0.0;
    for (double x : q) sum += h == Heuristic::Power ? x * x : x;
    return (h == Heuristic::Power ? q[i] * q[i] : q[i]) / sum;
}

// Random techniques: 2 to 5 of them, n in {0.25, 0.5, 1, 2, 3}, pdfs log-uniform in
// [10^lo, 10^hi], some of them 0 (at least one positive).
std::vector<Technique> randomTechniques(ps::Rng& rng, float lo, float hi) {
    std::vector<Technique> t(2 + rng.nextU32() % 4);
    const float ns[] = {0.25f, 0.5f, 1.0f, 2.0f, 3.0f};
    for (Technique& k : t) {
        k.n = ns[rng.nextU32() % 5];
        k.pdf = rng.uniform() < 0.15f ? 0.0f : std::pow(10.0f, lo + (hi - lo) * rng.uniform());
    }
    t[rng.nextU32() % t.size()].pdf = std::pow(10.0f, lo + (hi - lo) * rng.uniform());
    return t;
}

}  // namespace

TEST_CASE("mis: the weights of all techniques sum to 1 for any sample [2 pts]") {
    // 3000 random sets of 2 to 5 techniques per heuristic, pdfs from 1e-30 to 1e30 (and 0):
    // every weight in [0, 1], 0 for a technique with pdf 0, and the sum 1 (+- 1e-5).
    ps::Rng rng(ps::testseed::seed(21));
    for (Heuristic h : kHeuristics) {
        int failures = 0, sets = 0;
        for (int s = 0; s < 3000; ++s) {
            const std::vector<Technique> t = randomTechniques(rng, -30.0f, 30.0f);
            ++sets;
            double sum = 0.0;
            bool ok = true;
            std::ostringstream got;
            for (int i = 0; i < int(t.size()); ++i) {
                const float w = ps::misWeight(h, i, t.data(), int(t.size()));
                got << (i ? ", " : "") << w;
                ok = ok && std::isfinite(w) && w >= 0.0f && w <= 1.0f && (t[i].pdf > 0.0f || w == 0.0f);
                sum += w;
            }
            ok = ok && std::abs(sum - 1.0) <= 1e-5;
            if (!ok && ++failures <= 3)
                FAIL_CHECK(name(h) << " heuristic, techniques " << describe(t)
                                   << ":\n  expected weights in [0, 1] (0 where the pdf is 0) summing to 1, got "
                                   << got.str() << " (sum " << sum << ")");
        }
        CHECK_MESSAGE(failures == 0, name(h) << " heuristic: expected the weights of all " << sets
                                             << " random sets to sum to 1, got " << failures << " wrong");
    }
}

TEST_CASE("mis: the weights are the balance, power and maximum heuristics (Eq. 2.7-2.9) [2 pts]") {
    // Fixed cases first (easy to check by hand), then 1000 random sets per heuristic with pdfs
    // in [1e-3, 1e3], against the formulas in double (relative error <= 1e-5).
    const std::vector<Technique> two = {{1.0f, 3.0f}, {2.0f, 1.0f}};  // q = 3 and 2
    CHECK_MESSAGE(std::abs(ps::misWeight(Heuristic::Balance, 0, two.data(), 2) - 0.6f) < 1e-6f,
                  "balance, techniques " << describe(two) << ": expected w_0 = 3 / (3 + 2) = 0.6, got "
                                         << ps::misWeight(Heuristic::Balance, 0, two.data(), 2));
    CHECK_MESSAGE(std::abs(ps::misWeight(Heuristic::Power, 0, two.data(), 2) - 9.0f / 13.0f) < 1e-6f,
                  "power, techniques " << describe(two) << ": expected w_0 = 9 / (9 + 4) = 0.6923077, got "
                                       << ps::misWeight(Heuristic::Power, 0, two.data(), 2));
    CHECK_MESSAGE(ps::misWeight(Heuristic::Maximum, 0, two.data(), 2) == 1.0f,
                  "maximum, techniques " << describe(two) << ": expected w_0 = 1 (q_0 = 3 is the largest), got "
                                         << ps::misWeight(Heuristic::Maximum, 0, two.data(), 2));
    const std::vector<Technique> tie = {{1.0f, 2.0f}, {2.0f, 1.0f}, {1.0f, 0.5f}};  // q = 2, 2, 0.5
    CHECK_MESSAGE((ps::misWeight(Heuristic::Maximum, 0, tie.data(), 3) == 1.0f &&
                   ps::misWeight(Heuristic::Maximum, 1, tie.data(), 3) == 0.0f),
                  "maximum, techniques " << describe(tie) << " (q_0 = q_1 = 2): expected w = 1, 0, 0 (the first "
                                         << "of equals wins), got "
                                         << ps::misWeight(Heuristic::Maximum, 0, tie.data(), 3) << ", "
                                         << ps::misWeight(Heuristic::Maximum, 1, tie.data(), 3));
    ps::Rng rng(ps::testseed::seed(22));
    for (Heuristic h : kHeuristics) {
        int failures = 0, checks = 0;
        for (int s = 0; s < 1000; ++s) {
            const std::vector<Technique> t = randomTechniques(rng, -3.0f, 3.0f);
            for (int i = 0; i < int(t.size()); ++i) {
                const double expected = expectedWeight(h, i, t);
                const float w = ps::misWeight(h, i, t.data(), int(t.size()));
                ++checks;
                if (!(std::abs(w - expected) <= 1e-5 * std::max(1e-30, expected) + 1e-30) && ++failures <= 3)
                    FAIL_CHECK(name(h) << " heuristic, techniques " << describe(t) << ": expected w_" << i << " = "
                                       << expected << ", got " << w);
            }
        }
        CHECK_MESSAGE(failures == 0, name(h) << " heuristic: expected all " << checks << " weights right, got "
                                             << failures << " wrong");
    }
}

TEST_CASE("mis: the weights stay finite and right for pdfs from 1e-30 to 1e30 (Eq. 2.10) [1 pt]") {
    // A tiny bright light seen at a grazing angle has a huge solid-angle pdf: squared, 1e30
    // overflows a float; squared, two tiny pdfs underflow to 0. Each case: techniques, then the expected weights.
    struct Case {
        Heuristic h;
        std::vector<Technique> t;
        std::vector<double> w;
    };
    const std::vector<Case> cases = {
        {Heuristic::Power, {{1, 1e30f}, {1, 1.0f}}, {1.0, 0.0}},
        {Heuristic::Power, {{1, 1e30f}, {1, 1e30f}}, {0.5, 0.5}},
        {Heuristic::Power, {{1, 1e-30f}, {1, 2e-30f}}, {0.2, 0.8}},
        {Heuristic::Power, {{1, 3e25f}, {1, 4e25f}, {1, 0.0f}}, {9.0 / 25.0, 16.0 / 25.0, 0.0}},
        {Heuristic::Balance, {{1, 1e30f}, {1, 3e30f}}, {0.25, 0.75}},
        {Heuristic::Balance, {{1, 1e-30f}, {3, 1e-30f}}, {0.25, 0.75}},
        {Heuristic::Maximum, {{1, 1e30f}, {1, 2e30f}}, {0.0, 1.0}},
        {Heuristic::Maximum, {{1, 3e-30f}, {1, 2e-30f}}, {1.0, 0.0}},
    };
    for (const Case& c : cases)
        for (int i = 0; i < int(c.t.size()); ++i) {
            const float w = ps::misWeight(c.h, i, c.t.data(), int(c.t.size()));
            CHECK_MESSAGE((std::isfinite(w) && std::abs(w - c.w[i]) <= 1e-6),
                          name(c.h) << " heuristic, techniques " << describe(c.t) << ": expected w_" << i << " = "
                                    << c.w[i] << ", got " << w);
        }
}

TEST_CASE("mis: a point light's next-event sample has weight exactly 1 (Eq. 2.12) [2 pts]") {
    // 1. The other technique's pdf is 0: the weight is exactly 1, for any heuristic and any n.
    ps::Rng rng(ps::testseed::seed(23));
    int wrong = 0;
    for (Heuristic h : kHeuristics)
        for (int s = 0; s < 200; ++s) {
            const float n = 0.25f + 3.0f * rng.uniform(), p = std::pow(10.0f, -20.0f + 40.0f * rng.uniform());
            const float w = ps::misWeight(h, n, p, 0.5f, 0.0f);
            if (w != 1.0f && ++wrong <= 3)
                FAIL_CHECK(name(h) << " heuristic, techniques (n " << n << ", pdf " << p
                                   << ") and (n 0.5, pdf 0): expected weight exactly 1, got " << w);
        }
    CHECK_MESSAGE(wrong == 0,
                  "expected weight exactly 1 whenever the other technique's pdf is 0, got " << wrong << " wrong");

    // 2. Light samples of a point light are delta samples: pdfBSDF = 0, a positive value.
    const ps::Scene scene = loadSceneAt("scenes/cornell-point-light.scene", 16, 16);
    const Vec3 eye(278, 273, -800), floor(278, 0, 30);  // the floor, in front of the blocks
    ps::Ray ray(eye, glm::normalize(floor - eye));
    ps::SurfacePoint sp;
    REQUIRE(scene.intersect(ray, sp));
    const ps::DirectSample d = ps::sampleDirectLight(scene, sp, -ray.d, 0.5f, Vec2(0.5f));
    CHECK_MESSAGE(
        (d.delta && d.pdfBSDF == 0.0f && d.pdfLight == 1.0f && sum(d.value) > 0.0),
        "a light sample of the Cornell box's point light from the floor point "
            << str(sp.p)
            << ": expected delta = true, pdfBSDF = 0, pdfLight = 1 (the only light) and a positive value, got delta = "
            << d.delta << ", pdfBSDF = " << d.pdfBSDF << ", pdfLight = " << d.pdfLight << ", value " << str(d.value));

    // 3. So with a point light as the only light, every MIS estimator gives exactly the
    //    light-sampling image (the BSDF samples find no emitter; all draw the same numbers).
    const Render light = render(scene, "direct-light", 4, ps::testseed::seed(24));
    LESSON02_CHECK_FINITE(light);
    double total = 0.0;
    for (const Color& c : light.mean.pixels) total += sum(c);
    CHECK_MESSAGE(total > 0.0, "direct-light on the point-lit Cornell box: expected a lit image, got a black one");
    for (const std::string algo : {"direct-balance", "direct-power", "direct-max"}) {
        const Render mis = render(scene, algo, 4, ps::testseed::seed(24));
        LESSON02_CHECK_FINITE(mis);
        int differ = 0, first = -1;
        for (size_t i = 0; i < mis.mean.pixels.size(); ++i)
            if (mis.mean.pixels[i] != light.mean.pixels[i] && differ++ == 0) first = int(i);
        CHECK_MESSAGE(differ == 0,
                      algo << " on the point-lit Cornell box (16 x 16, 4 spp, seed 24): expected exactly "
                           << "the direct-light image (next-event weight 1, BSDF samples find no "
                           << "emitter), got " << differ << " different pixels; the first, (" << first % 16 << ", "
                           << first / 16 << "): "
                           << (first >= 0 ? str(mis.mean.pixels[first]) + " instead of " + str(light.mean.pixels[first])
                                          : std::string()));
    }
}
