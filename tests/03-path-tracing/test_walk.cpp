// Lesson 3, graded: the random walk itself (cameraWalk, Eq. 3.3-3.5), seen through a visitor that
// records every vertex it is shown. Exact checks: the walk is replayed here step by step with a
// copy of its random number generator (the framework's sampleBSDF, lesson 3's
// survivalProbability), so every vertex, throughput and roulette decision is known in advance.
#include <vector>
#include "format.h"
#include "lesson03.h"
#include "seed.h"

using namespace lesson03;

namespace {


// What a failure message stream holds.
std::string text(std::ostream& o) { return static_cast<std::ostringstream&>(o).str(); }

// Every vertex the walk shows, in order (the visitor draws no random numbers).
std::vector<ps::WalkVertex> recordWalk(const ps::Scene& scene, const ps::Ray& ray, ps::Rng& rng, int maxDepth) {
    std::vector<ps::WalkVertex> seen;
    ps::cameraWalk(scene, ray, rng, maxDepth, [&](const ps::WalkVertex& v) {
        seen.push_back(v);
        return seen.size() < 10000;  // a walk that never ends is cut here (and fails)
    });
    return seen;
}

std::string bounceList(const std::vector<ps::WalkVertex>& seen) {
    std::string s;
    for (size_t i = 0; i < seen.size() && i < 12; ++i) s += (i ? ", " : "") + std::to_string(seen[i].bounces);
    return seen.empty() ? "none" : s + (seen.size() > 12 ? ", ..." : "");
}

bool closeColor(const Color& a, const Color& b) {
    auto close = [](float x, float y) {
        return std::abs(x - y) <= 1e-5f * std::max(std::abs(x), std::abs(y)) + 1e-30f;
    };
    return close(a.r, b.r) && close(a.g, b.g) && close(a.b, b.b);
}

// Replays the walk of Eq. 3.4, 3.5 from `ray` with `rng` (a copy of the walk's generator) and
// compares it with what the visitor was shown. Returns "" or what is wrong. C++ leaves the order
// in which a call's arguments are evaluated to the compiler: sampleBSDF(..., rng.uniform2(),
// rng.uniform(), ...) may draw either number first. inOrder = false replays the call as written
// (this compiler's order), inOrder = true draws uniform2 and then uniform into variables; a walk
// is accepted if it matches either.
bool sampleInOrder(const ps::Material& m, const Vec3& n, const Vec3& wo, ps::Rng& rng, ps::BSDFSample& s) {
    const Vec2 u = rng.uniform2();
    const float uLobe = rng.uniform();
    return ps::sampleBSDF(m, n, wo, u, uLobe, ps::Transport::Radiance, s);
}

std::string replay(const ps::Scene& scene, ps::Ray ray, ps::Rng rng, int maxDepth,
                   const std::vector<ps::WalkVertex>& seen, bool inOrder) {
    std::ostringstream why;
    // What x_k must show: x_0 has beta 1 and counts as specular (the camera ray).
    Color beta(1.0f);
    float pdfPrev = 0.0f;
    Vec3 pPrev(0.0f);
    bool specular = true;
    for (int k = 0;; ++k) {
        ps::SurfacePoint sp;
        const bool hit = scene.intersect(ray, sp);
        if (size_t(k) >= seen.size()) {
            why << "the visitor was shown " << seen.size() << " vertices (bounces " << bounceList(seen)
                << "), expected vertex " << k << " too (the walk went on after vertex " << k - 1 << ")";
            return why.str();
        }
        const ps::WalkVertex& v = seen[size_t(k)];
        why << "vertex " << k << ": ";
        if (v.bounces != k) return text(why << "expected bounces = " << k << ", got " << v.bounces);
        if (v.hit != hit)
            return text(why << "expected hit = " << hit << " (the ray "
                            << (hit ? "hits " + str(sp.p) : "leaves the scene") << "), got " << v.hit);
        if (hit && glm::length(v.sp.p - sp.p) > 1e-4f * (1.0f + ps::maxAbsComponent(sp.p)))
            return text(why << "expected the hit point " << str(sp.p) << ", got " << str(v.sp.p));
        if (glm::length(v.wo + ray.d) > 1e-6f)
            return text(why << "expected wo = -ray.d = " << str(-ray.d) << ", got " << str(v.wo));
        if (!closeColor(v.beta, beta))
            return text(why << "expected the throughput beta = " << str(beta)
                            << " (Eq. 3.4: the product of sampleBSDF's "
                            << "weights, each survivor divided by its q, Eq. 3.5), got " << str(v.beta));
        if (v.specular != specular)
            return text(why << "expected specular = " << specular
                            << (k == 0 ? " (the camera ray)" : " (the delta flag of the BSDF sample that led here)")
                            << ", got " << v.specular);
        if (k > 0 && !(std::abs(v.pdfPrev - pdfPrev) <= 1e-6f * pdfPrev))
            return text(why << "expected pdfPrev = " << pdfPrev << " (the pdf of the BSDF sample that led here), got "
                            << v.pdfPrev);
        if (k > 0 && glm::length(v.pPrev - pPrev) > 1e-4f * (1.0f + ps::maxAbsComponent(pPrev)))
            return text(why << "expected pPrev = " << str(pPrev) << " (the previous vertex), got " << str(v.pPrev));
        why.str("");
        std::string end;
        ps::BSDFSample s;
        float q = 1.0f;
        if (!hit) end = "the ray left the scene";
        else if (k == maxDepth) end = "it has maxDepth = " + std::to_string(maxDepth) + " bounces (Eq. 3.3)";
        else if (!(inOrder ? sampleInOrder(scene.materials[size_t(sp.material)], sp.n, -ray.d, rng, s)
                           : ps::sampleBSDF(scene.materials[size_t(sp.material)], sp.n, -ray.d, rng.uniform2(),
                                            rng.uniform(), ps::Transport::Radiance, s)))
            end = "its BSDF sample failed";
        else {
            beta *= s.weight;
            specular = s.delta;
            pdfPrev = s.pdf;
            pPrev = sp.p;
            q = ps::survivalProbability(beta, k + 1);
            if (ps::isBlack(beta)) end = "the throughput is black";
            else if (q < 1.0f && rng.uniform() >= q) end = "Russian roulette ended it (q = " + ps::fmt::num(q) + ")";
            else if (q < 1.0f) beta /= q;
        }
        if (!end.empty()) {
            if (seen.size() != size_t(k) + 1)
                return text(why << "expected the walk to end after vertex " << k << " (" << end
                                << "), but the visitor was shown " << seen.size() << " vertices (bounces "
                                << bounceList(seen) << ")");
            return "";
        }
        ray = scene.spawnRay(sp, s.wi);
    }
}

struct ReplayCase {
    std::string name;
    ps::Scene scene;
    int maxDepth;
};

}  // namespace

TEST_CASE(
    "random walk: the visitor sees x_0 .. x_D, one call per vertex, and the walk stops at maxdepth (Eq. 3.3) [1 pt]") {
    // The closed cube furnace with albedo 1: nothing is absorbed and the throughput stays 1, so
    // Russian roulette never ends a walk (q = 1) and only the maximum depth D does. Every walk
    // must show exactly the vertices with 0, 1, ..., D bounces, in that order, all hits.
    const ps::Scene scene = furnace(Enclosure::Cube, 1.0f, 1.0f);
    for (int D : {0, 1, 2, 5}) {
        for (int i = 0; i < 20; ++i) {
            ps::Rng rng = ps::taskRng(ps::testseed::seed(391), uint32_t(D), uint32_t(i));
            const Vec3 d = ps::sampleUniformSphere(rng.uniform2());
            const std::vector<ps::WalkVertex> seen = recordWalk(scene, ps::Ray(scene.camera.position(), d), rng, D);
            bool inOrder = seen.size() == size_t(D) + 1;
            for (size_t k = 0; inOrder && k < seen.size(); ++k)
                inOrder = seen[k].bounces == int(k) && seen[k].hit && seen[k].beta == Color(1.0f);
            std::string hint;
            if (seen.size() == size_t(D) + 2)
                hint =
                    ": one vertex too many, the walk must end right after visiting the vertex with bounces == maxDepth";
            else if (seen.size() == size_t(D))
                hint = ": one vertex too few, the vertex with bounces == maxDepth must be visited too";
            else if (seen.empty()) hint = ": the visitor was never called";
            CHECK_MESSAGE(inOrder, "closed cube furnace (albedo 1, so beta stays 1 and q = 1), maxdepth "
                                       << D << ", walk " << i << ": expected " << D + 1
                                       << " vertices with bounces 0 .. " << D << ", all hits with beta (1, 1, 1), got "
                                       << seen.size() << " (bounces " << bounceList(seen) << ")" << hint);
            if (!inOrder) break;
        }
    }
}

TEST_CASE(
    "random walk: each vertex's throughput, roulette and next hit follow the BSDF sample (Eq. 3.4, 3.5) [2 pts]") {
    // 200 walks in each of three scenes, replayed here with a copy of the walk's generator: a
    // coloured furnace with maxdepth 60 (Russian roulette ends most walks; beta must be divided
    // by q, with q = survivalProbability(beta, bounces + 1) and its number drawn only when q < 1),
    // the Cornell spheres (a mirror and glass: delta samples, the specular flag) and the open
    // Cornell box under a sky (walks that leave the scene: the escape is their last vertex).
    std::vector<ReplayCase> cases;
    {
        std::string s = readText(sourcePath("scenes/furnace.scene"));
        s = ps::scenetext::replaceAll(s, "albedo 0.5 0.5 0.5", "albedo 0.9 0.6 0.3");
        cases.push_back(
            {"closed cube furnace, albedo (0.9, 0.6, 0.3)", ps::parseScene(s, "furnace (test_walk.cpp)"), 60});
    }
    cases.push_back({"cornell-spheres.scene", loadSceneAt("scenes/cornell-spheres.scene", 32, 32), 8});
    cases.push_back({"cornell-background.scene", loadSceneAt("scenes/cornell-background.scene", 32, 32), 8});
    for (const ReplayCase& c : cases) {
        const ps::Camera& camera = c.scene.camera;
        int checked = 0, roulette = 0;
        for (int i = 0; i < 200; ++i) {
            ps::Rng rng = ps::taskRng(ps::testseed::seed(392), 0, uint32_t(i));
            const Vec2 raster{rng.uniform() * float(camera.width()), rng.uniform() * float(camera.height())};
            const ps::Ray ray = camera.generateRay(raster);
            const ps::Rng before = rng;
            const std::vector<ps::WalkVertex> seen = recordWalk(c.scene, ray, rng, c.maxDepth);
            std::string wrong = replay(c.scene, ray, before, c.maxDepth, seen, false);
            if (!wrong.empty() && replay(c.scene, ray, before, c.maxDepth, seen, true).empty()) wrong.clear();
            CHECK_MESSAGE(wrong.empty(), c.name << ", maxdepth " << c.maxDepth << ", walk " << i << " through pixel "
                                                << ps::fmt::str(raster) << ": " << wrong);
            if (!wrong.empty()) break;
            ++checked;
            roulette += seen.size() > 4;
        }
        CHECK_MESSAGE(checked == 200, c.name << ": " << checked << " of 200 walks as expected");
        if (c.maxDepth == 60)
            CHECK_MESSAGE(roulette > 20, "test setup: the furnace should give walks long enough for the roulette");
    }
}

TEST_CASE(
    "random walk: a ray that leaves the scene is shown as the last vertex, and the visitor can end the walk [1 pt]") {
    // A floor under a sky: a camera ray that misses is one vertex (hit = false, bounces 0,
    // beta 1, specular); one that hits the floor bounces off it into the sky, so its walk shows
    // exactly two vertices, the floor and the escape. A visitor that returns false ends the walk
    // at once: no further vertex and no further random number.
    const ps::Scene scene = ps::parseScene(
        "camera eye 0 1 -3  target 0 0 0  fov 60  resolution 8 8\n"
        "material floor diffuse albedo 0.5 0.5 0.5\n"
        "quad -2 0 -2  -2 0 2  2 0 2  2 0 -2  material floor\n"
        "background radiance 1 1 1\n",
        "floor under a sky (test_walk.cpp)");
    const Vec3 eye = scene.camera.position();
    {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(393), 0, 0);
        const std::vector<ps::WalkVertex> seen = recordWalk(scene, ps::Ray(eye, Vec3(0.0f, 1.0f, 0.0f)), rng, 5);
        const bool ok = seen.size() == 1 && !seen[0].hit && seen[0].bounces == 0 && seen[0].beta == Color(1.0f) &&
                        seen[0].specular && glm::length(seen[0].wo - Vec3(0.0f, -1.0f, 0.0f)) < 1e-6f;
        CHECK_MESSAGE(
            ok,
            "a camera ray straight up into the sky, maxdepth 5: expected one vertex with hit = false, bounces 0, "
            "beta (1, 1, 1), specular, wo (0, -1, 0), got "
                << seen.size() << " vertices"
                << (seen.empty() ? std::string()
                                 : ", the first with hit = " + std::to_string(seen[0].hit) + ", bounces " +
                                       std::to_string(seen[0].bounces) + ", beta " + str(seen[0].beta)));
    }
    const ps::Ray down(eye, glm::normalize(Vec3(0.3f, 0.0f, 0.2f) - eye));
    for (int i = 0; i < 20; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(394), 0, uint32_t(i));
        const std::vector<ps::WalkVertex> seen = recordWalk(scene, down, rng, 5);
        const bool ok = seen.size() == 2 && seen[0].hit && seen[0].bounces == 0 && !seen[1].hit &&
                        seen[1].bounces == 1 && closeColor(seen[1].beta, Color(0.5f));
        CHECK_MESSAGE(
            ok, "a camera ray onto a diffuse floor (albedo 0.5) under a sky, maxdepth 5, walk "
                    << i << ": expected two vertices, the floor (bounces 0) and the escape into the sky (hit = false, "
                    << "bounces 1, beta = sampleBSDF's weight (0.5, 0.5, 0.5)), got " << seen.size() << " (bounces "
                    << bounceList(seen) << ")");
        if (!ok) break;
    }
    {
        const ps::Scene cube = furnace(Enclosure::Cube, 1.0f, 1.0f);
        ps::Rng rng = ps::taskRng(ps::testseed::seed(395), 0, 0);
        ps::Rng copy = rng;
        int calls = 0;
        ps::cameraWalk(cube, ps::Ray(cube.camera.position(), Vec3(0.0f, 0.0f, 1.0f)), rng, 10,
                       [&](const ps::WalkVertex& v) {
                           ++calls;
                           return v.bounces < 1;  // go on after x_0, end at x_1
                       });
        // One BSDF sample (uniform2, uniform) after x_0; q = 1 at the first bounce: no roulette number.
        copy.uniform2();
        copy.uniform();
        const bool sameNumbers = rng.uniform() == copy.uniform() && rng.uniform() == copy.uniform();
        CHECK_MESSAGE(
            (calls == 2 && sameNumbers),
            "closed cube furnace, maxdepth 10, a visitor that returns false at the vertex with 1 bounce: expected "
            "2 visits and the walk to end there with nothing drawn after its one BSDF sample, got "
                << calls << " visits" << (sameNumbers ? "" : ", and a different number of random numbers drawn"));
    }
}
