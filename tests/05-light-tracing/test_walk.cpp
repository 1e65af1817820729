// Lesson 5, graded: the particle's random walk itself (lightWalk, Eq. 5.1, 5.2, 5.6-5.8 with
// lesson 3's Russian roulette, Eq. 3.5), seen through a visitor that records every vertex it is
// shown. Exact checks: the walk is replayed here step by step with a copy of its random number
// generator (lesson 5's startLightPath and sampleAdjointBSDF, lesson 3's survivalProbability).
#include <vector>
#include "lesson05.h"
#include "seed.h"

using namespace lesson05;

namespace {

// What a failure message stream holds.
std::string text(std::ostream& o) { return static_cast<std::ostringstream&>(o).str(); }

struct Seen {
    ps::WalkVertex v;
    ps::LightPathStart start;  // a copy of the start the walk handed the visitor
};

std::vector<Seen> recordWalk(const ps::Scene& scene, ps::Rng& rng, int maxDepth, int stopAt = -1,
                             ps::SurvivalFunction survival = ps::survivalProbability) {
    std::vector<Seen> seen;
    ps::lightWalk(scene, rng, {maxDepth, survival}, [&](const ps::WalkVertex& v, const ps::LightPathStart& start) {
        seen.push_back({v, start});
        return v.bounces != stopAt && seen.size() < 10000;
    });
    return seen;
}

// A survival function other than lesson 3's: 0.7 at every bounce.
float survivalSeventy(const Color&, int) { return 0.7f; }

std::string bounceList(const std::vector<Seen>& seen) {
    std::string s;
    for (size_t i = 0; i < seen.size() && i < 12; ++i) s += (i ? ", " : "") + std::to_string(seen[i].v.bounces);
    return seen.empty() ? "none" : s + (seen.size() > 12 ? ", ..." : "");
}

bool closeColor(const Color& a, const Color& b) {
    auto close = [](float x, float y) {
        return std::abs(x - y) <= 1e-5f * std::max(std::abs(x), std::abs(y)) + 1e-30f;
    };
    return close(a.r, b.r) && close(a.g, b.g) && close(a.b, b.b);
}
bool closePoint(const Vec3& a, const Vec3& b) { return glm::length(a - b) <= 1e-4f * (1.0f + ps::maxAbsComponent(b)); }

// Replays the particle's walk with `rng` (a copy of the walk's generator) and compares it with
// what the visitor was shown. Returns "" or what is wrong. C++ leaves the order in which a call's
// arguments are evaluated to the compiler: startLightPath(scene, rng.uniform(), rng.uniform2(),
// rng.uniform2()) may draw its numbers in another order than written. inOrder = false replays
// the calls as written (this compiler's order), inOrder = true draws the numbers left to right
// into variables first; a walk is accepted if it matches either.
std::string replay(const ps::Scene& scene, ps::Rng rng, int maxDepth, const std::vector<Seen>& seen, bool inOrder,
                   ps::SurvivalFunction survival = ps::survivalProbability,
                   const char* survivalName = "survivalProbability") {
    std::ostringstream why;
    ps::LightPathStart start;
    if (inOrder) {
        const float u1 = rng.uniform();
        const Vec2 u2 = rng.uniform2();
        const Vec2 u3 = rng.uniform2();
        start = ps::startLightPath(scene, u1, u2, u3);
    } else {
        start = ps::startLightPath(scene, rng.uniform(), rng.uniform2(), rng.uniform2());
    }
    if (!start.valid) {
        if (seen.empty()) return "";
        return text(why << "startLightPath gives no valid start here, expected no vertex, got " << seen.size());
    }
    if (seen.empty())
        return "expected y0 (startLightPath with the walk's first numbers, uniform, uniform2, uniform2) first, the visitor was never called";
    const Seen& y0 = seen[0];
    if (y0.v.bounces != 0 || y0.start.light != start.light || !closePoint(y0.v.sp.p, start.y0.p) ||
        !closeColor(y0.v.beta, start.beta))
        return text(
            why
            << "expected the first vertex to be y0 = startLightPath(rng.uniform(), rng.uniform2(), rng.uniform2()).y0 = "
            << str(start.y0.p) << " on light " << start.light << " (bounces 0, beta = start.beta " << str(start.beta)
            << "), got bounces " << y0.v.bounces << ", point " << str(y0.v.sp.p) << ", light " << y0.start.light
            << ", beta " << str(y0.v.beta));
    Color beta = start.beta, throughput(1.0f);
    ps::Ray ray = start.ray;
    for (int k = 1;; ++k) {
        std::string end;
        ps::SurfacePoint sp;
        if (k > maxDepth) end = "maxDepth = " + std::to_string(maxDepth) + " bounces";
        else if (!scene.intersect(ray, sp)) end = "the particle left the scene (a miss is not a vertex)";
        if (!end.empty()) {
            if (seen.size() == size_t(k)) return "";
            return text(why << "expected " << k << " vertices, bounces 0 .. " << k - 1 << " (then " << end
                            << "), the visitor was shown " << seen.size() << " (bounces " << bounceList(seen) << ")");
        }
        if (seen.size() <= size_t(k))
            return text(why << "the visitor was shown " << seen.size() << " vertices (bounces " << bounceList(seen)
                            << "), expected the particle's hit with " << k << " bounces too (at " << str(sp.p) << ")");
        const ps::WalkVertex& v = seen[size_t(k)].v;
        why << "vertex " << k << ": ";
        if (v.bounces != k) return text(why << "expected bounces = " << k << ", got " << v.bounces);
        if (!closePoint(v.sp.p, sp.p))
            return text(why << "expected the hit point " << str(sp.p) << ", got " << str(v.sp.p));
        if (glm::length(v.wo + ray.d) > 1e-6f)
            return text(why << "expected wo = -ray.d = " << str(-ray.d)
                            << " (towards where the particle came from), got " << str(v.wo));
        if (!closeColor(v.beta, beta))
            return text(why << "expected the particle's power beta = " << str(beta)
                            << " (start.beta times the adjoint weights, "
                            << "each survivor divided by q = " << survivalName
                            << "(throughput, bounces), the throughput since the light "
                            << "being " << str(throughput) << "), got " << str(v.beta));
        why.str("");
        if (k == maxDepth) continue;  // the loop's next round ends it
        ps::BSDFSample s;
        bool sampled;
        if (inOrder) {
            const Vec2 u = rng.uniform2();
            const float uLobe = rng.uniform();
            sampled = ps::sampleAdjointBSDF(scene.materials[size_t(sp.material)], sp.n, -ray.d, u, uLobe, s);
        } else {
            sampled = ps::sampleAdjointBSDF(scene.materials[size_t(sp.material)], sp.n, -ray.d, rng.uniform2(),
                                            rng.uniform(), s);
        }
        if (!sampled) end = "its adjoint BSDF sample failed";
        else {
            beta *= s.weight;
            throughput *= s.weight;
            const float q = survival(throughput, k);
            if (ps::isBlack(beta)) end = "its power is black";
            else if (q < 1.0f && rng.uniform() >= q) end = "Russian roulette ended it (q = " + num(q) + ")";
            else if (q < 1.0f) {
                beta /= q;
                throughput /= q;
            }
        }
        if (!end.empty()) {
            if (seen.size() == size_t(k) + 1) return "";
            return text(why << "expected the walk to end after vertex " << k << " (" << end
                            << "), the visitor was shown " << seen.size() << " vertices (bounces " << bounceList(seen)
                            << ")");
        }
        ray = scene.spawnRay(sp, s.wi);
    }
}

}  // namespace

TEST_CASE("light walk: y0 first, then one vertex per bounce up to maxdepth, and the visitor can end it [1 pt]") {
    // The closed cube furnace with albedo 1: every wall emits, nothing is absorbed, the throughput
    // since the light stays 1, so Russian roulette never ends a walk (q = 1): every walk shows
    // y0 on a wall and then exactly the hits with 1 .. D bounces.
    std::string text = readText(sourcePath("scenes/furnace.scene"));
    text = ps::scenetext::replaceAll(text, "albedo 0.5 0.5 0.5", "albedo 1 1 1");
    const ps::Scene scene = ps::parseScene(text, "furnace, albedo 1 (test_walk.cpp)");
    for (int D : {0, 1, 2, 5}) {
        for (int i = 0; i < 20; ++i) {
            ps::Rng rng = ps::taskRng(ps::testseed::seed(591), uint32_t(D), uint32_t(i));
            ps::Rng copy = rng, copyInOrder = rng;
            const std::vector<Seen> seen = recordWalk(scene, rng, D);
            const ps::LightPathStart start =
                ps::startLightPath(scene, copy.uniform(), copy.uniform2(), copy.uniform2());
            // The same numbers drawn left to right into variables (the compiler may evaluate the
            // call's arguments above in another order; either is accepted, as in replay()).
            const float uLight = copyInOrder.uniform();
            const Vec2 uPos = copyInOrder.uniform2();
            const Vec2 uDir = copyInOrder.uniform2();
            const ps::LightPathStart startInOrder = ps::startLightPath(scene, uLight, uPos, uDir);
            const bool y0Ok = !seen.empty() &&
                              (closePoint(seen[0].v.sp.p, start.y0.p) || closePoint(seen[0].v.sp.p, startInOrder.y0.p));
            bool ok = seen.size() == size_t(D) + 1 && y0Ok;
            for (size_t k = 0; ok && k < seen.size(); ++k) ok = seen[k].v.bounces == int(k);
            std::string hint;
            if (seen.size() == size_t(D) + 2)
                hint =
                    ": one vertex too many, the walk must end right after visiting the vertex with bounces == maxDepth";
            else if (seen.size() == size_t(D))
                hint = ": one vertex too few, the vertex with bounces == maxDepth must be visited too";
            else if (seen.empty()) hint = ": the visitor was never called";
            else if (!y0Ok)
                hint =
                    ": the first vertex must be y0 = startLightPath(...).y0 = " + str(start.y0.p) + ", with start set";
            CHECK_MESSAGE(ok, "closed cube furnace (albedo 1: q = 1), maxdepth "
                                  << D << ", walk " << i << ": expected " << D + 1
                                  << " vertices, y0 (bounces 0) then bounces 1 .. " << D << ", got " << seen.size()
                                  << " (bounces " << bounceList(seen) << ")" << hint);
            if (!ok) break;
        }
    }
    // A visitor that returns false at y0: one visit, and no number drawn after startLightPath's.
    ps::Rng rng = ps::taskRng(ps::testseed::seed(592), 0, 0), copy = rng;
    const std::vector<Seen> seen = recordWalk(scene, rng, 10, 0);
    for (int n = 0; n < 5; ++n) copy.uniform();
    const bool sameNumbers = rng.uniform() == copy.uniform() && rng.uniform() == copy.uniform();
    CHECK_MESSAGE(
        (seen.size() == 1 && sameNumbers),
        "closed cube furnace, maxdepth 10, a visitor that returns false at y0: expected 1 visit and no random number "
        "drawn after startLightPath's five, got "
            << seen.size() << " visits" << (sameNumbers ? "" : " and more numbers drawn"));
    // A visitor that returns false at the vertex after two bounces: the walk ends there (3 visits).
    for (int i = 0; i < 20; ++i) {
        ps::Rng r = ps::taskRng(ps::testseed::seed(595), 0, uint32_t(i));
        const std::vector<Seen> two = recordWalk(scene, r, 10, 2);
        CHECK_MESSAGE(two.size() == 3,
                      "closed cube furnace (albedo 1: q = 1), maxdepth 10, a visitor that returns "
                      "false at the vertex with 2 bounces: expected 3 visits (bounces 0, 1, 2), got "
                          << two.size() << " (bounces " << bounceList(two)
                          << "; the visitor's answer after y0 ignored?)");
        if (two.size() != 3) break;
    }
    // A scene without lights has no particle: no vertex at all.
    const ps::Scene dark = ps::parseScene(
        "camera eye 0 1 -3  target 0 1 0  fov 60  resolution 4 4\n"
        "material white diffuse albedo 0.5 0.5 0.5\n"
        "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material white\n",
        "a floor without a light (test_walk.cpp)");
    ps::Rng r = ps::taskRng(ps::testseed::seed(596), 0, 0);
    const std::vector<Seen> none = recordWalk(dark, r, 10);
    CHECK_MESSAGE(none.empty(), "a scene without lights: expected no vertex (no light to start from), got "
                                    << none.size() << " (bounces " << bounceList(none) << ")");
}

TEST_CASE(
    "light walk: the particle's power and the roulette follow the adjoint BSDF, q from the throughput since the light (Eq. 5.7, 3.5) [2 pts]") {
    // 200 walks in each of three scenes, replayed here with a copy of the walk's generator: a
    // coloured furnace whose walls emit 50 (start.beta is large, so a roulette on beta instead of
    // the throughput since the light would never fire; maxdepth 60), the Cornell spheres (glass
    // and a mirror: the adjoint's delta lobes) and the open Cornell box under a sky (particles
    // from the background's disk, and particles that leave the scene).
    struct Case {
        std::string name;
        ps::Scene scene;
        int maxDepth;
    };
    std::vector<Case> cases;
    {
        std::string s = readText(sourcePath("scenes/furnace.scene"));
        s = ps::scenetext::replaceAll(s, "albedo 0.5 0.5 0.5", "albedo 0.9 0.6 0.3");
        s = ps::scenetext::replaceAll(s, "emission 1 1 1", "emission 50 50 50");
        cases.push_back({"closed cube furnace, albedo (0.9, 0.6, 0.3), emission 50",
                         ps::parseScene(s, "furnace (test_walk.cpp)"), 60});
    }
    cases.push_back({"cornell-spheres.scene", loadSceneAt("scenes/cornell-spheres.scene", 32, 32), 8});
    cases.push_back({"cornell-background.scene", loadSceneAt("scenes/cornell-background.scene", 32, 32), 8});
    for (const Case& c : cases) {
        int checked = 0, long_ = 0;
        for (int i = 0; i < 200; ++i) {
            ps::Rng rng = ps::taskRng(ps::testseed::seed(593), 0, uint32_t(i));
            const ps::Rng before = rng;
            const std::vector<Seen> seen = recordWalk(c.scene, rng, c.maxDepth);
            std::string wrong = replay(c.scene, before, c.maxDepth, seen, false);
            if (!wrong.empty() && replay(c.scene, before, c.maxDepth, seen, true).empty()) wrong.clear();
            CHECK_MESSAGE(wrong.empty(),
                          c.name << ", maxdepth " << c.maxDepth << ", light path " << i << ": " << wrong);
            if (!wrong.empty()) break;
            ++checked;
            long_ += seen.size() > 5;
        }
        CHECK_MESSAGE(checked == 200, c.name << ": " << checked << " of 200 walks as expected");
        if (c.maxDepth == 60)
            CHECK_MESSAGE(long_ > 20, "test setup: the furnace should give walks long enough for the roulette");
    }
    // The walk plays its roulette with the survival function it is given (lesson 8's photons
    // pass their own): here q = 0.7 at every bounce, on the coloured furnace.
    const Case& furnace = cases[0];
    for (int i = 0; i < 100; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(594), 0, uint32_t(i));
        const ps::Rng before = rng;
        const std::vector<Seen> seen = recordWalk(furnace.scene, rng, furnace.maxDepth, -1, survivalSeventy);
        std::string wrong = replay(furnace.scene, before, furnace.maxDepth, seen, false, survivalSeventy, "survival");
        if (!wrong.empty() &&
            replay(furnace.scene, before, furnace.maxDepth, seen, true, survivalSeventy, "survival").empty())
            wrong.clear();
        CHECK_MESSAGE(wrong.empty(),
                      furnace.name << ", lightWalk(..., survival) with survival = 0.7 at every bounce, light path " << i
                                   << ": " << wrong << " (q must come from the survival function passed in)");
        if (!wrong.empty()) break;
    }
}

namespace {
// A direction sampler of the test's own: cosine-weighted about the normal on wo's side, with the
// adjoint weight of a Lambertian surface (its albedo). Counts its calls.
struct CountingSampler : ps::DirectionSampler {
    mutable int calls = 0;
    bool sample(const ps::Scene& scene, const ps::WalkVertex& v, ps::Rng& rng, ps::BSDFSample& s) const override {
        ++calls;
        const Vec3 n = glm::dot(v.sp.n, v.wo) < 0.0f ? -v.sp.n : v.sp.n;
        s.wi = ps::Frame(n).toWorld(ps::sampleCosineHemisphere(rng.uniform2()));
        s.pdf = pdf(scene, v, s.wi);
        s.delta = false;
        s.weight = scene.materials[size_t(v.sp.material)].albedo;
        return s.pdf > 0.0f;
    }
    float pdf(const ps::Scene&, const ps::WalkVertex& v, const Vec3& wi) const override {
        const float c = glm::dot(wi, v.sp.n) * (glm::dot(v.wo, v.sp.n) < 0.0f ? -1.0f : 1.0f);
        return c > 0.0f ? c / ps::kPi : 0.0f;
    }
};
}  // namespace

TEST_CASE("light walk: the walk's options reach lesson 3's walk: direction sampler and continuation rule [1 pt]") {
    // The closed cube furnace (every particle hits a wall), maxdepth 3: the options' sampler must
    // pick every direction after y1, y2 (y0's is the emission's), and a rule of two continuations
    // with beta / 2 at every surface must branch the particle's walk depth first.
    const ps::Scene scene = ps::parseScene(readText(sourcePath("scenes/furnace.scene")), "furnace (test_walk.cpp)");
    CountingSampler sampler;
    ps::WalkOptions opt(3, ps::alwaysSurvive);
    opt.sampler = &sampler;
    int rules = 0;
    opt.continuation = [&](const ps::WalkVertex& v, ps::Rng&) {
        ++rules;
        return ps::Continuations{2, v.beta * 0.5f};
    };
    for (uint32_t i = 0; i < 8; ++i) {
        sampler.calls = rules = 0;
        ps::Rng rng = ps::taskRng(ps::testseed::seed(595), 0, i);
        std::string order;
        ps::lightWalk(scene, rng, opt, [&](const ps::WalkVertex& v, const ps::LightPathStart&) {
            order += std::to_string(v.bounces) + " ";
            return true;
        });
        const std::string want = "0 1 2 3 3 2 3 3 ";
        CHECK_MESSAGE(order == want,
                      "lightWalk with a continuation rule of 2 at every surface, maxdepth 3: expected the "
                      "bounces "
                          << want << "(depth first: the rule and the options go to lesson 3's walk), got " << order);
        CHECK_MESSAGE(rules == 3, "lightWalk: the options' continuation rule must be asked at y1 and the two y2s, got "
                                      << rules << " times");
        CHECK_MESSAGE(sampler.calls == 6,
                      "lightWalk: the options' direction sampler must pick the 6 directions that "
                      "leave y1 and the y2s, it was asked "
                          << sampler.calls << " times");
        if (order != want) break;
    }
}
