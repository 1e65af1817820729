// Lesson 3, graded: the walk's extension points (walk.h), which later algorithms set and lesson 3's
// own estimators leave at their defaults: a continuation rule (splitting and roulette at a vertex,
// Eq. 3.10) and a direction sampler (how the walk leaves a non-delta vertex), whose density MIS
// must use (Eq. 3.7). The rules and the sampler are the test's own.
#include <cmath>
#include <string>
#include <vector>
#include "lesson03.h"
#include "seed.h"

using namespace lesson03;

namespace {

struct Seen {
    int bounces;
    bool hit;
    Color beta;
};

std::vector<Seen> walkWith(const ps::Scene& scene, const ps::WalkOptions& opt, uint32_t i) {
    std::vector<Seen> seen;
    ps::Rng rng = ps::taskRng(ps::testseed::seed(3101), 0, i);
    const Vec3 d = ps::sampleUniformSphere(rng.uniform2());
    ps::cameraWalk(scene, ps::Ray(scene.camera.position(), d), rng, opt, [&](const ps::WalkVertex& v) {
        seen.push_back({v.bounces, v.hit, v.beta});
        return seen.size() < 10000;
    });
    return seen;
}

std::string bounces(const std::vector<Seen>& seen) {
    std::string s;
    for (const Seen& v : seen) s += std::to_string(v.bounces) + " ";
    return s;
}

// The bounces of a complete tree with n continuations at every vertex, depth first.
void fullTree(int k, int maxDepth, int n, std::string& s) {
    s += std::to_string(k) + " ";
    if (k < maxDepth)
        for (int i = 0; i < n; ++i) fullTree(k + 1, maxDepth, n, s);
}

// Uniform directions on the hemisphere of the side wo is on: not the BSDF's density, so a walk
// and an MIS weight that use the BSDF's instead of this one are told apart. Counts its calls.
struct UniformHemisphere : ps::DirectionSampler {
    mutable int calls = 0, deltaCalls = 0;
    bool sample(const ps::Scene& scene, const ps::WalkVertex& v, ps::Rng& rng, ps::BSDFSample& s) const override {
        ++calls;
        const ps::Material& m = scene.materials[size_t(v.sp.material)];
        if (m.isDelta()) ++deltaCalls;
        const Vec3 n = glm::dot(v.sp.n, v.wo) < 0.0f ? -v.sp.n : v.sp.n;
        s.wi = ps::Frame(n).toWorld(ps::sampleUniformHemisphere(rng.uniform2()));
        s.pdf = pdf(scene, v, s.wi);
        s.delta = false;
        s.weight = ps::evalBSDF(m, v.sp.n, v.wo, s.wi) * (std::abs(glm::dot(v.sp.n, s.wi)) / s.pdf);
        return true;
    }
    float pdf(const ps::Scene&, const ps::WalkVertex& v, const Vec3& wi) const override {
        return glm::dot(wi, v.sp.n) * glm::dot(v.wo, v.sp.n) > 0.0f ? 1.0f / (2.0f * ps::kPi) : 0.0f;
    }
};

}  // namespace

TEST_CASE(
    "random walk: a continuation rule's continuations are walked depth first, each with the rule's throughput "
    "(Eq. 3.10) [1 pt]") {
    // The cube furnace with albedo 0.5 (every ray hits a wall, every BSDF sample's weight 0.5), no
    // Russian roulette: the rule alone says how often the walk goes on.
    const ps::Scene scene = furnace(Enclosure::Cube, 0.5f, 1.0f);
    constexpr int kDepth = 3;
    struct Case {
        const char* what;
        std::function<ps::Continuations(const ps::WalkVertex&)> rule;
        int n;                       // continuations at every vertex
        double step;                 // beta's factor per bounce
        const char* tree = nullptr;  // the bounces expected, if not the full tree of n
    };
    const std::vector<Case> cases = {
        {"two continuations, each with beta / 2",
         [](const ps::WalkVertex& v) {
             return ps::Continuations{2, v.beta * 0.5f};
         },
         2, 0.25},
        {"three continuations, each with beta / 3",
         [](const ps::WalkVertex& v) {
             return ps::Continuations{3, v.beta / 3.0f};
         },
         3, 0.5 / 3.0},
        {"one continuation with 4 beta",
         [](const ps::WalkVertex& v) {
             return ps::Continuations{1, v.beta * 4.0f};
         },
         1, 2.0},
        {"none: the walk ends at its first vertex",
         [](const ps::WalkVertex& v) {
             return ps::Continuations{0, v.beta};
         },
         0, 1.0},
        // Every continuation of a split can end at the vertex it leaves (here: a black throughput),
        // the extra ones too: each of the two vertices after one bounce then ends its walk.
        {"two continuations with beta / 2, black ones after the first bounce",
         [](const ps::WalkVertex& v) {
             return v.bounces == 1 ? ps::Continuations{2, Color(0.0f)} : ps::Continuations{2, v.beta * 0.5f};
         },
         2, 0.25, "0 1 1 "},
    };
    for (const Case& c : cases) {
        ps::WalkOptions opt(kDepth, ps::alwaysSurvive);
        int asked = 0;
        opt.continuation = [&](const ps::WalkVertex& v, ps::Rng&) {
            ++asked;
            return c.rule(v);
        };
        for (uint32_t i = 0; i < 8; ++i) {
            asked = 0;
            const std::vector<Seen> seen = walkWith(scene, opt, i);
            std::string want = c.tree ? c.tree : "";
            if (!c.tree) fullTree(0, kDepth, c.n, want);
            CHECK_MESSAGE(bounces(seen) == want, "a rule of " << c.what << " at every vertex, maxDepth " << kDepth
                                                              << ": expected the vertices' bounces in depth-first "
                                                                 "order (every continuation walked to its end "
                                                                 "before the next one leaves)\n  "
                                                              << want << "\n got\n  " << bounces(seen));
            int inner = 0;
            for (const Seen& v : seen) inner += v.bounces < kDepth ? 1 : 0;
            CHECK_MESSAGE(asked == inner, "a rule of " << c.what << ": the rule must be asked once at every vertex the "
                                                       << "walk may go on from (" << inner
                                                       << " here, not at maxDepth), got " << asked);
            for (const Seen& v : seen) {
                const double want = std::pow(c.step, v.bounces);
                if (!(std::abs(double(v.beta.r) - want) <= 1e-5 * want)) {
                    CHECK_MESSAGE(false, "a rule of " << c.what << ": the vertex after " << v.bounces
                                                      << " bounces must carry the rule's throughput times the BSDF "
                                                         "weights 0.5, beta = "
                                                      << want << ", got " << v.beta.r
                                                      << " (a continuation leaves with the rule's beta, not the "
                                                         "vertex's)");
                    break;
                }
            }
            if (bounces(seen) != want) break;
        }
    }
}

TEST_CASE(
    "random walk: a rule that decides survival itself turns the walk's roulette off for its continuations (Eq. 3.5, "
    "3.10) [1 pt]") {
    // The cube furnace with albedo 0.5 and a survival function of q = 1/2 after every bounce. A
    // rule that returns one continuation with roulette = false (it decided at the vertex) must see
    // every walk reach maxDepth with beta = 0.5^k; one that leaves the decision to the walk
    // (roulette = true) must see the walk's roulette: some walks end early, the survivors carry
    // beta / q = 1.
    const ps::Scene scene = furnace(Enclosure::Cube, 0.5f, 1.0f);
    constexpr int kDepth = 4;
    for (const bool roulette : {false, true}) {
        ps::WalkOptions opt(kDepth, [](const Color&, int) { return 0.5f; });
        opt.continuation = [roulette](const ps::WalkVertex& v, ps::Rng&) {
            ps::Continuations c{1, v.beta};
            c.roulette = roulette;
            return c;
        };
        int full = 0, wrongBeta = 0;
        for (uint32_t i = 0; i < 16; ++i) {
            const std::vector<Seen> seen = walkWith(scene, opt, i);
            if (int(seen.size()) == kDepth + 1) ++full;
            for (const Seen& v : seen) {
                const double want = roulette ? 1.0 : std::pow(0.5, v.bounces);
                if (!(std::abs(double(v.beta.r) - want) <= 1e-5 * want)) ++wrongBeta;
            }
        }
        if (!roulette)
            CHECK_MESSAGE((full == 16 && wrongBeta == 0),
                          "a rule whose continuations say roulette = false (it decided survival itself), under a "
                          "survival function of q = 1/2: expected all 16 walks to reach maxDepth "
                              << kDepth << " with beta = 0.5^k (no roulette after their bounces), got " << full
                              << " complete walks and " << wrongBeta << " vertices with another beta");
        else
            CHECK_MESSAGE((full < 16 && wrongBeta == 0),
                          "a rule whose continuations say roulette = true, under a survival function of q = 1/2: "
                          "expected the walk's roulette after every bounce (some of 16 walks end early, the "
                          "survivors carry beta / q = 1), got "
                              << full << " complete walks and " << wrongBeta << " vertices with another beta");
    }
}

TEST_CASE(
    "random walk: a direction sampler picks every non-delta direction, never a delta one, and MIS weighs with its "
    "density (Eq. 3.7) [2 pts]") {
    // 1. Who samples: a mirror floor under a diffuse ceiling; the sampler must be asked at every
    //    diffuse vertex the walk leaves and never at the mirror, and each vertex's pdfPrev is the
    //    density of the sample that led there (the sampler's 1 / 2 pi after the ceiling).
    const char* kScene = R"(
camera eye 0 1 0  target 0 0 1  fov 40  resolution 1 1
material chrome mirror albedo 1 1 1
material white diffuse albedo 0.8 0.8 0.8
quad -50 0 -50  -50 0 50  50 0 50  50 0 -50  material chrome
quad -50 2 -50  50 2 -50  50 2 50  -50 2 50  material white
)";
    const ps::Scene room = ps::parseScene(kScene, "mirror floor, white ceiling (test_extensions.cpp)");
    UniformHemisphere sampler;
    ps::WalkOptions opt(12, ps::alwaysSurvive);
    opt.sampler = &sampler;
    int left = 0, wrongPdf = 0, wrongSampler = 0;
    std::string firstPdf;
    for (uint32_t i = 0; i < 64; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(3102), 0, i);
        const Vec3 d = glm::normalize(Vec3{rng.uniform() - 0.5f, -1.0f, rng.uniform() - 0.5f});
        bool prevDiffuse = false;
        ps::cameraWalk(room, ps::Ray(room.camera.position(), d), rng, opt, [&](const ps::WalkVertex& v) {
            if (v.sampler != &sampler) ++wrongSampler;
            if (prevDiffuse && std::abs(v.pdfPrev - 1.0f / (2.0f * ps::kPi)) > 1e-6f && wrongPdf++ == 0)
                firstPdf = "after a diffuse vertex, pdfPrev " + num(v.pdfPrev);
            if (!v.hit) return false;
            prevDiffuse = !room.materials[size_t(v.sp.material)].isDelta();
            if (prevDiffuse && v.bounces < 12) ++left;
            return true;
        });
    }
    CHECK_MESSAGE(sampler.deltaCalls == 0, "the walk handed a mirror vertex to its direction sampler "
                                               << sampler.deltaCalls
                                               << " times: a delta BSDF is always sampled by "
                                                  "the walk's own BSDF sampling");
    CHECK_MESSAGE(sampler.calls == left,
                  "the walk left " << left << " diffuse vertices: its direction sampler (WalkOptions::sampler) "
                                   << "must pick each of those directions, it was asked " << sampler.calls << " times");
    CHECK_MESSAGE(wrongPdf == 0,
                  "pdfPrev must be the density of the direction sample that led to the vertex (the "
                  "sampler's 1 / (2 pi) = "
                      << num(1.0 / (2.0 * 3.14159265358979)) << "); " << wrongPdf << " wrong, first " << firstPdf);
    CHECK_MESSAGE(wrongSampler == 0, "every vertex must show the walk's direction sampler (WalkVertex::sampler), "
                                         << wrongSampler << " did not");

    // 2. MIS with the sampler's density: the sphere furnace (albedo 0.5, Le 1, maxDepth 5), lesson
    //    3's MIS visitor on a walk that samples uniform directions. Light samples and uniform BSDF
    //    hits are weighted against each other; with the sampler's density on both sides the
    //    weights of every direction add up to 1 and the mean is Eq. 3.8; with the BSDF's cosine
    //    density on the light sample's side they do not (about 3 % too little here).
    const ps::Scene sphere = furnace(Enclosure::Sphere, 0.5f, 1.0f);
    constexpr int kMaxDepth = 5, kRays = 30000;
    ps::WalkOptions mis(kMaxDepth);
    mis.sampler = &sampler;
    ps::stats::Welford w;
    int bad = 0;
    for (int i = 0; i < kRays; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(3103), 0, uint32_t(i));
        const Vec3 d = ps::sampleUniformSphere(rng.uniform2());
        Color L(0.0f);
        ps::cameraWalk(sphere, ps::Ray(sphere.camera.position(), d), rng, mis, [&](const ps::WalkVertex& v) {
            ps::addMISContribution(sphere, v, rng, kMaxDepth, L);
            return true;
        });
        if (!ps::isFinite(L)) ++bad;
        else w.add(sum(L));
    }
    const double expected = 3.0 * furnaceRadiance(0.5, 1.0, kMaxDepth);
    const ps::stats::TTestResult t = ps::stats::tTest(w, expected, alpha(), 0.004);
    CHECK_MESSAGE(bad == 0, bad << " samples were NaN or Inf");
    CHECK_MESSAGE(t.passed,
                  "pt's MIS on a walk whose direction sampler is uniform on the hemisphere, sphere furnace "
                  "(albedo 0.5, maxDepth 5): expected "
                      << expected << " (Eq. 3.8), got " << t.mean << " +- " << t.stdError << " (p = " << t.pValue
                      << "): the light sample's MIS weight must use the density with which the walk itself "
                         "leaves the vertex (pdfWalk), not the BSDF's\n"
                      << t.report);
}
