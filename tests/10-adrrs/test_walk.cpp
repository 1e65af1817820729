// Lesson 10, graded: the walk with survival and splitting (Algorithm 10.1) in a closed box (every
// ray hits a wall of albedo 0.5, so every BSDF sample's weight is 0.5), with rules of the test's own
// and the uniform numbers replayed: the tree's vertices in depth-first order, their throughputs,
// the numbers drawn, the cap on the paths of one camera ray; and pt-adrrs's image for 1 and 2
// threads.
#include "lesson10.h"
#include <functional>

using namespace lesson10;

namespace {

struct Visit {
    int bounces;
    bool hit;
    Color beta;
    // The bookkeeping of lesson 3's vertex: where the path is, where it came from and with which
    // solid-angle pdf, whether that was a specular (delta) sample.
    Vec3 p, n, wo, pPrev;
    float pdfPrev;
    bool specular;
    int material;
};

Visit visitOf(const ps::WalkVertex& v) {
    return {v.bounces, v.hit, v.beta, v.sp.p, v.sp.n, v.wo, v.pPrev, v.pdfPrev, v.specular, v.sp.material};
}

struct Walked {
    std::vector<Visit> visits;
    size_t numbers = 0;
};

Walked walk(const ps::Scene& scene, int maxDepth, float q, float u, const std::function<bool(int)>& goOn = nullptr) {
    Replay replay;
    replay.fill = u;
    ps::Rng rng;
    rng.replayFrom(&replay);
    Walked w;
    const ps::Ray ray(Vec3(0.5f), glm::normalize(Vec3(0.1f, -0.2f, 1.0f)));
    ps::splittingWalk(
        scene, ray, rng, maxDepth, [&](const ps::WalkVertex&) { return q; },
        [&](const ps::WalkVertex& v) {
            w.visits.push_back(visitOf(v));
            return goOn ? goOn(v.bounces) : true;
        });
    w.numbers = replay.read;
    return w;
}

std::string sequence(const std::vector<Visit>& visits) {
    std::string s;
    for (const Visit& v : visits) s += std::to_string(v.bounces) + " ";
    return s;
}

// The bounces of a complete tree with n continuations everywhere, depth first.
void fullTree(int bounces, int maxDepth, int n, std::string& s) {
    s += std::to_string(bounces) + " ";
    if (bounces < maxDepth)
        for (int i = 0; i < n; ++i) fullTree(bounces + 1, maxDepth, n, s);
}

// Every vertex's bookkeeping, step by step, against the vertex it came from (the last one visited
// with one bounce less: the tree is walked depth first): the camera ray's vertex has pdfPrev 0 and
// is specular (nothing to weigh against: lesson 3's convention), wo the reversed camera ray; every
// later vertex has pPrev = its parent's point, wo pointing back there, and after a diffuse parent
// pdfPrev = the framework's pdfBSDF of that direction there (cos / pi) and not specular; after a
// mirror, the mirror's own sample's pdf (the lobe's probability) and specular.
void checkBookkeeping(const ps::Scene& scene, const Walked& w, float q) {
    std::vector<const Visit*> parents;
    for (size_t i = 0; i < w.visits.size(); ++i) {
        const Visit& v = w.visits[i];
        std::string bad;
        if (v.bounces == 0) {
            const Vec3 camera = -glm::normalize(Vec3(0.1f, -0.2f, 1.0f));
            if (v.pdfPrev != 0.0f) bad = "pdfPrev " + num(v.pdfPrev) + " at the camera ray's vertex (expected 0)";
            else if (!v.specular) bad = "the camera ray's vertex not marked specular (lesson 3: specular at bounces 0)";
            else if (glm::length(v.wo - camera) > 1e-5f) bad = "wo " + str(v.wo) + ", expected " + str(camera);
        } else {
            REQUIRE(size_t(v.bounces) <= parents.size());
            const Visit& parent = *parents[size_t(v.bounces) - 1];
            const Vec3 back = glm::normalize(parent.p - v.p);
            const ps::Material& m = scene.materials[size_t(parent.material)];
            ps::BSDFSample s;
            const bool delta =
                m.isDelta() && ps::sampleBSDF(m, parent.n, parent.wo, ps::Vec2(0.5f), 0.5f, ps::Transport::Radiance, s);
            const float pdf = delta ? s.pdf : ps::pdfBSDF(m, parent.n, parent.wo, -back);
            if (glm::length(v.pPrev - parent.p) > 1e-5f)
                bad = "pPrev " + str(v.pPrev) + ", expected the previous vertex " + str(parent.p);
            else if (std::abs(v.pdfPrev - pdf) > 1e-4f * pdf)
                bad = "pdfPrev " + num(v.pdfPrev) + ", expected the BSDF sample's solid-angle pdf " + num(pdf) +
                      " at the previous vertex";
            else if (v.specular != delta)
                bad = delta ? "not marked specular after a mirror" : "marked specular after a diffuse bounce";
            else if (glm::length(v.wo - back) > 1e-4f)
                bad = "wo " + str(v.wo) + ", expected the direction back to the previous vertex " + str(back);
        }
        CHECK_MESSAGE(bad.empty(), "splittingWalk, rule q = " << q << ", vertex " << i << " (bounces " << v.bounces
                                                              << ", depth-first order): " << bad);
        if (!bad.empty()) return;
        parents.resize(size_t(v.bounces));
        parents.push_back(&v);
    }
}

void checkTree(float q, float u, int n, const char* what) {
    const ps::Scene scene = closedBox(0.5f, 8, false);
    constexpr int kDepth = 3;
    const Walked w = walk(scene, kDepth, q, u);
    std::string want;
    fullTree(0, kDepth, n, want);
    CHECK_MESSAGE(sequence(w.visits) == want, "splittingWalk, rule q = " << q << ", every uniform number " << u
                                                                         << ", maxDepth 3 (" << what
                                                                         << "): expected the vertices' bounces in "
                                                                            "depth-first order\n  "
                                                                         << want << "\n got\n  " << sequence(w.visits));
    bool betaOk = true, hitOk = true;
    std::string firstBad;
    for (const Visit& v : w.visits) {
        const double want = std::pow(0.5 / double(q), v.bounces);
        const bool ok = std::abs(v.beta.r - want) <= 1e-5 * want && v.beta.r == v.beta.g && v.beta.g == v.beta.b;
        if (!ok && betaOk)
            firstBad = "bounces " + std::to_string(v.bounces) + ": expected " + num(want) + ", got " + str(v.beta);
        betaOk = betaOk && ok;
        hitOk = hitOk && v.hit;
    }
    CHECK_MESSAGE(betaOk, "splittingWalk, rule q = " << q << " (" << what
                                                     << "): a vertex after k bounces must have beta = (albedo / q)^k = "
                                                        "(0.5 / q)^k (each continuation carries beta / q); "
                                                     << firstBad);
    CHECK_MESSAGE(hitOk, "splittingWalk in a closed box: every vertex must be a hit");
    checkBookkeeping(scene, w, q);
    // Numbers: one per decision where q is not whole (decisions at the vertices with bounces <
    // maxDepth), three per BSDF sample (one per continuation).
    size_t decisions = 0, samples = 0;
    for (const Visit& v : w.visits) {
        if (v.bounces < kDepth) ++decisions;
        if (v.bounces > 0) ++samples;
    }
    const size_t numbers = (q == std::floor(q) ? 0 : decisions) + 3 * samples;
    CHECK_MESSAGE(w.numbers == numbers,
                  "splittingWalk, rule q = " << q << " (" << what << "): expected " << numbers << " uniform numbers ("
                                             << (q == std::floor(q) ? "none" : "one")
                                             << " per decision, 3 per BSDF sample), got " << w.numbers);
}

}  // namespace

TEST_CASE("splitting walk: the tree of paths, depth first, each continuation with beta / q (Algorithm 10.1) [2 pts]") {
    checkTree(1.5f, 0.25f, 2, "u below q - floor(q): two continuations everywhere");
    checkTree(1.5f, 0.75f, 1, "u above q - floor(q): one continuation everywhere");
    checkTree(0.5f, 0.25f, 1, "q < 1, u below q: the path survives");
    checkTree(0.5f, 0.75f, 0, "q < 1, u above q: roulette ends the path at the camera ray's vertex");
    checkTree(3.0f, 0.9f, 3, "a whole q: exactly 3 continuations, no number drawn");

    // A mirror where the camera looks (the wall z = 1): specular vertices in the tree, each
    // vertex's bookkeeping replayed step by step.
    checkBookkeeping(closedBox(0.5f, 3, false, 4, true), walk(closedBox(0.5f, 3, false, 4, true), 3, 1.5f, 0.25f),
                     1.5f);

    // A continuation whose BSDF sample fails (a Phong lobe below the surface) ends alone: the
    // next continuation of the same vertex still samples and goes on. A Phong floor (exponent 1)
    // seen at a grazing angle, q = 2 (whole: no number drawn for n), maxDepth 1; the numbers a, a, a
    // (a failing sample, whatever order the three are read in) then b, b, b (one that succeeds and
    // leaves the scene), both found here with the framework's sampleBSDF.
    {
        const ps::Scene floor = ps::parseScene(
            "camera eye 0 1 0  target 1 0.9 0  fov 40  resolution 4 4\n"
            "material glossy phong albedo 0.8 0.8 0.8 exponent 1\n"
            "quad -9 0 -9  -9 0 9  9 0 9  9 0 -9  material glossy\n",
            "phong-floor.scene");
        const ps::Ray ray(Vec3(0, 0.1f, 0), glm::normalize(Vec3(1, -0.05f, 0)));
        const Vec3 n(0, 1, 0), wo = -ray.d;
        float a = -1.0f, b = -1.0f;
        for (int i = 1; i < 1000 && (a < 0.0f || b < 0.0f); ++i) {
            const float u = float(i) / 1000.0f;
            ps::BSDFSample s;
            const bool ok = ps::sampleBSDF(floor.materials[0], n, wo, ps::Vec2(u, u), u, ps::Transport::Radiance, s);
            if (!ok && a < 0.0f) a = u;
            if (ok && b < 0.0f && s.wi.y > 0.0f) b = u;
        }
        REQUIRE_MESSAGE((a > 0.0f && b > 0.0f), "the test's own layout: a failing and a succeeding Phong sample");
        Replay replay;
        replay.values = {a, a, a, b, b, b};
        replay.fill = b;
        ps::Rng rng;
        rng.replayFrom(&replay);
        std::vector<int> bounces;
        ps::splittingWalk(
            floor, ray, rng, 1, [](const ps::WalkVertex&) { return 2.0f; },
            [&](const ps::WalkVertex& v) {
                bounces.push_back(v.bounces);
                return true;
            });
        std::string got;
        for (int k : bounces) got += std::to_string(k) + " ";
        CHECK_MESSAGE(got == "0 1 ",
                      "splittingWalk, q = 2 at a Phong floor whose first continuation's BSDF sample "
                      "fails: expected the vertices 0 1 (that continuation ends, the second goes "
                      "on), got "
                          << got);
        CHECK_MESSAGE(replay.read == 6,
                      "splittingWalk, q = 2, the first sample failing: expected 6 uniform numbers "
                      "read (3 per BSDF sample, none for a whole q), got "
                          << replay.read);
    }

    // The visitor ends a branch.
    const ps::Scene scene = closedBox(0.5f, 8, false);
    const Walked w = walk(scene, 3, 2.0f, 0.5f, [](int bounces) { return bounces < 1; });
    CHECK_MESSAGE(sequence(w.visits) == "0 1 1 ",
                  "splittingWalk, rule q = 2, the visitor says stop at bounces 1: expected the vertices 0 1 1, got "
                      << sequence(w.visits));
}

TEST_CASE(
    "splitting walk: a camera ray starts at most kMaxPathsPerCameraRay paths, then q <= 1 (Algorithm 10.1) [1 pt]") {
    // q = 8 everywhere, maxDepth 2: the camera ray's vertex starts 8 paths; its first four
    // continuations split into 8 each while fewer than 32 paths have been started (8, 15, 22, 29:
    // after the fourth, 36); the last four go on once (q cut to 1).
    const ps::Scene scene = closedBox(0.5f, 8, false);
    const Walked w = walk(scene, 2, 8.0f, 0.5f);
    std::string want = "0 ";
    for (int i = 0; i < 8; ++i) {
        want += "1 ";
        for (int j = 0; j < (i < 4 ? 8 : 1); ++j) want += "2 ";
    }
    CHECK_MESSAGE(
        sequence(w.visits) == want,
        "splittingWalk, rule q = 8, maxDepth 2: expected 8 continuations at bounces 0, 8 at each of the first four "
        "vertices with 1 bounce (paths started: 8, 15, 22, 29, then 36 >= kMaxPathsPerCameraRay = 32) and "
        "1 at the last four:\n  "
            << want << "\n got\n  " << sequence(w.visits));
    // beta: 1, then 0.5 / 8 after the first bounce; after the second 0.5 / 8 * 0.5 / 8 below a split
    // and 0.5 / 8 * 0.5 / 1 below a vertex whose q was cut to 1 (its one continuation carries beta / 1).
    std::vector<double> betas = {1.0};
    for (int i = 0; i < 8; ++i) {
        betas.push_back(0.5 / 8.0);
        for (int j = 0; j < (i < 4 ? 8 : 1); ++j) betas.push_back(0.5 / 8.0 * (i < 4 ? 0.5 / 8.0 : 0.5));
    }
    bool betaOk = w.visits.size() == betas.size();
    for (size_t i = 0; betaOk && i < betas.size(); ++i)
        betaOk = std::abs(w.visits[i].beta.r - betas[i]) <= 1e-5 * betas[i];
    CHECK_MESSAGE(betaOk,
                  "splittingWalk, rule q = 8 with the cap: expected beta = 0.5 / 8 after one bounce, "
                  "(0.5 / 8)^2 below the four splits and 0.5 / 8 * 0.5 below the four vertices whose q was "
                  "cut to 1 (a continuation carries beta divided by the q actually used)");
}

TEST_CASE(
    "splitting walk: where the rule cannot decide, the walk is lesson 3's, its roulette included (Algorithm 10.1) [1 pt]") {
    // A rule that never decides (kNoDecision) must leave exactly lesson 3's camera walk: the same
    // vertices, throughputs and random numbers as cameraWalk with lesson 3's roulette, over 32
    // rays of up to 12 bounces in a closed box of albedo 0.5 (the roulette plays from bounce 3).
    const ps::Scene scene = closedBox(0.5f, 12, false);
    int differ = 0, tooShort = 0;
    std::string first;
    for (uint32_t i = 0; i < 32; ++i) {
        const ps::Ray ray(Vec3(0.5f), glm::normalize(Vec3(0.1f + 0.05f * float(i), -0.2f, 1.0f)));
        std::vector<Visit> mine, pt;
        ps::Rng a = ps::taskRng(ps::testseed::seed(1031), 0, i), b = a;
        ps::splittingWalk(
            scene, ray, a, 12, [](const ps::WalkVertex&) { return ps::kNoDecision; },
            [&](const ps::WalkVertex& v) {
                mine.push_back(visitOf(v));
                return true;
            });
        ps::cameraWalk(scene, ray, b, {12}, [&](const ps::WalkVertex& v) {
            pt.push_back(visitOf(v));
            return true;
        });
        // Independent of lesson 3's walk: in a closed box nothing ends a walk before the roulette
        // plays, so every walk visits its first three bounces at least.
        if (mine.size() < 3) ++tooShort;
        bool same = mine.size() == pt.size() && a.nextU32() == b.nextU32();
        for (size_t k = 0; same && k < mine.size(); ++k) same = mine[k].beta == pt[k].beta;
        if (!same && differ++ == 0)
            first = "ray " + std::to_string(i) + ": lesson 3's walk visits the bounces " + sequence(pt) +
                    "(roulette from bounce 3), splittingWalk " + sequence(mine);
    }
    CHECK_MESSAGE(differ == 0,
                  "splittingWalk with a rule that never decides (kNoDecision): expected lesson 3's "
                  "camera walk, its roulette included (same vertices, throughputs and random numbers); "
                      << differ << " of 32 rays differ, the first: " << first);
    CHECK_MESSAGE(tooShort == 0, "splittingWalk with a rule that never decides: "
                                     << tooShort
                                     << " of 32 walks in a closed box visited fewer than 3 vertices "
                                        "(nothing ends a walk there before lesson 3's roulette plays)");
}

TEST_CASE("pt-adrrs: the same image and counts for 1 and 2 threads [1 pt]") {
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 16, 16);
    const auto run = [&](int threads) {
        ps::ADRRSPathTracer adrrs;
        ps::RenderOptions opt;
        opt.spp = 4;
        opt.seed = ps::testseed::seed(1001);
        opt.threads = threads;
        const ps::RenderResult r = ps::render(scene, adrrs, opt);
        return std::make_pair(r.film.mean(), adrrs.counts());
    };
    const auto one = run(1), two = run(2);
    double total = 0.0;
    for (const Color& c : one.first.pixels) total += ps::testrender::sum(c);
    CHECK_MESSAGE((total > 0.0 && one.second.vertices > 0),
                  "pt-adrrs on the Cornell box (16 x 16, 4 spp): expected a lit image, got the sum of all pixels "
                      << total << " from " << one.second.vertices << " path vertices");
    size_t differ = 0;
    for (size_t i = 0; i < one.first.pixels.size(); ++i)
        if (one.first.pixels[i] != two.first.pixels[i]) ++differ;
    CHECK_MESSAGE(differ == 0,
                  "pt-adrrs on the Cornell box (16 x 16, 4 spp): expected the same image for 1 and 2 "
                  "threads (every number of a camera ray's tree from its pixel's generator), "
                      << differ << " pixels differ");
    CHECK_MESSAGE((one.second.vertices == two.second.vertices && one.second.wasted == two.second.wasted),
                  "pt-adrrs: expected the same counts for 1 and 2 threads, got " << one.second.vertices << " and "
                                                                                 << two.second.vertices << " vertices");
}
