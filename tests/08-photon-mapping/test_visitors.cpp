// Lesson 8, graded: the two visitors through which a later algorithm works with pm's pieces
// (photonmap.h). The photon visitor sees every vertex of a photon path after pm's own decision
// there, sorts the photon about to be stored into a population, and may drop it and end the walk.
// The gather visitor decides, term by term, what pm's camera side adds (Eq. 8.11): the emission,
// the light sample (whose numbers are drawn either way), its own caustic and global estimates, and
// whether the walk goes on. Exact: the same random numbers with and without a visitor, so the
// photons and the terms are compared one by one. The visitors are the test's own.
#include <vector>
#include "lesson08.h"
#include "tasks.h"

using namespace lesson08;

namespace {

ps::Scene spheres() { return loadSceneAt("scenes/cornell-spheres.scene", 16, 16); }

struct Call {
    int bounces;
    bool photon;
};

// One photon path with a visitor (nullptr: none), from path i's own generator.
std::vector<Photon> tracePath(const ps::Scene& scene, ps::MapKind kind, uint32_t i, const ps::PhotonVisitor& visit) {
    std::vector<Photon> out;
    ps::Rng rng = ps::taskRng(ps::testseed::seed(871), 0, i);
    ps::tracePhoton(scene, rng, 8, kind, 1000, out, visit);
    return out;
}

// Vertex j of photon path i: 1 if its surface is specular, 2 if not (the test's own look, from a
// visitor that only records).
int endKind(const ps::Scene& scene, ps::MapKind kind, uint32_t i, int j) {
    int k = 2;
    tracePath(scene, kind, i, [&](const ps::WalkVertex& v, Photon*) {
        if (v.bounces == j) k = scene.materials[size_t(v.sp.material)].isDelta() ? 1 : 2;
        return true;
    });
    return k;
}

}  // namespace

TEST_CASE("photons: the photon visitor sees every vertex, sorts the photons and ends the walk [1 pt]") {
    // The Cornell spheres (a mirror and a glass sphere), 300 photon paths of each map, each traced
    // without a visitor and again with one: the visitor that keeps everything sees y_0, y_1, ...
    // in order, a photon exactly where one is stored, and the stored photons are the same (their
    // population the one it set: the vertex's bounces); the visitor that refuses the first photon
    // ends the walk there: nothing stored, no vertex after it.
    const ps::Scene scene = spheres();
    int stored = 0, ended = 0;
    // Where the walks were ended: y_0, a specular vertex, a surface without a photon, one with.
    int endedAt[4] = {0, 0, 0, 0};
    for (ps::MapKind kind : {ps::MapKind::Global, ps::MapKind::Caustic}) {
        const char* name = kind == ps::MapKind::Global ? "global" : "caustic";
        for (uint32_t i = 0; i < 300; ++i) {
            const std::vector<Photon> plain = tracePath(scene, kind, i, nullptr);
            std::vector<Call> calls;
            const std::vector<Photon> sorted = tracePath(scene, kind, i, [&](const ps::WalkVertex& v, Photon* ph) {
                calls.push_back({v.bounces, ph != nullptr});
                if (ph) ph->population = uint8_t(v.bounces);
                return true;
            });
            REQUIRE_MESSAGE(!calls.empty(),
                            name << " path " << i << ": the visitor was never called (not even at y_0)");
            CHECK_MESSAGE((calls[0].bounces == 0 && !calls[0].photon),
                          name << " path " << i << ": the first call is not y_0 without a photon");
            std::vector<int> photonBounces;
            for (size_t k = 0; k < calls.size(); ++k) {
                CHECK_MESSAGE(calls[k].bounces == int(k), name << " path " << i << ": call " << k << " sees the vertex "
                                                               << calls[k].bounces << " (every vertex once, in order)");
                if (calls[k].photon) photonBounces.push_back(calls[k].bounces);
            }
            REQUIRE_MESSAGE(sorted.size() == plain.size(), name << " path " << i << ": " << plain.size()
                                                                << " photons without the visitor, " << sorted.size()
                                                                << " with one that keeps them all");
            CHECK_MESSAGE(photonBounces.size() == plain.size(), name << " path " << i << ": the visitor was handed "
                                                                     << photonBounces.size() << " photons, "
                                                                     << plain.size() << " were stored");
            for (size_t k = 0; k < plain.size() && k < photonBounces.size(); ++k) {
                CHECK_MESSAGE((sorted[k].p == plain[k].p && sorted[k].power == plain[k].power),
                              name << " path " << i << ": photon " << k << " differs with the visitor");
                CHECK_MESSAGE(int(sorted[k].population) == photonBounces[k],
                              name << " path " << i << ": photon " << k << " has population "
                                   << int(sorted[k].population) << ", the visitor set " << photonBounces[k]);
            }
            stored += int(plain.size());
            // A visitor that ends the walk at vertex j, whatever is there (y_0, a mirror or glass, a
            // surface where this map stores nothing, one where it stores a photon): no vertex after
            // j, and exactly the photons stored before j.
            const size_t vertices = calls.size();
            for (size_t j = 0; j < vertices; ++j) {
                int seen = 0;
                const std::vector<Photon> cut = tracePath(scene, kind, i, [&](const ps::WalkVertex& v, Photon*) {
                    ++seen;
                    return v.bounces != int(j);
                });
                size_t before = 0;
                while (before < photonBounces.size() && photonBounces[before] < int(j)) ++before;
                endedAt[j == 0 ? 0 : calls[j].photon ? 3 : endKind(scene, kind, i, int(j))]++;
                CHECK_MESSAGE((seen == int(j) + 1 && cut.size() == before),
                              name << " path " << i << ": a visitor that ends the walk at vertex " << j << " of "
                                   << vertices << ": expected " << j + 1 << " vertices seen and the " << before
                                   << " photons stored before it, got " << seen << " vertices and " << cut.size()
                                   << " photons");
            }
            if (plain.empty()) continue;
            calls.clear();
            const std::vector<Photon> refused = tracePath(scene, kind, i, [&](const ps::WalkVertex& v, Photon* ph) {
                calls.push_back({v.bounces, ph != nullptr});
                return ph == nullptr;
            });
            CHECK_MESSAGE(refused.empty(), name << " path " << i << ": " << refused.size()
                                                << " photons stored although the visitor refused the first");
            int handed = 0;
            for (const Call& c : calls) handed += c.photon;
            CHECK_MESSAGE((handed == 1 && calls.back().photon),
                          name << " path " << i << ": the walk went on after the visitor returned false (" << handed
                               << " photons handed to it, " << calls.size() << " vertices)");
            ++ended;
        }
    }
    REQUIRE_MESSAGE((stored > 100 && ended > 20),
                    "the test's paths store " << stored << " photons (" << ended << " paths with one)");
    CHECK_MESSAGE((endedAt[0] > 0 && endedAt[1] > 0 && endedAt[2] > 0 && endedAt[3] > 0),
                  "the test ended walks at y_0 " << endedAt[0] << ", at specular vertices " << endedAt[1]
                                                 << ", at surfaces without a photon " << endedAt[2] << ", with one "
                                                 << endedAt[3] << " times (it needs each)");
}

namespace {

// The gather visitor whose terms are pm's own, each kept or left out.
struct Terms {
    bool emission = true, lightSample = true, caustic = true, global = true;
};

ps::GatherVisitor only(const Terms& t, const ps::PhotonMaps& maps, const ps::PmOptions& opt) {
    ps::GatherVisitor g;
    g.emission = [t](const ps::WalkVertex&) { return t.emission; };
    g.lightSample = [t](const ps::WalkVertex&) { return t.lightSample; };
    g.caustic = [t, &maps, &opt](const ps::WalkVertex& x, const ps::Material& m) {
        return t.caustic ? ps::radianceEstimate(maps.caustic, x.sp, m, x.wo, opt.causticEstimate) : Color(0.0f);
    };
    g.global = [t, &maps, &opt](const ps::SurfacePoint&, int, const ps::SurfacePoint& y, const ps::Material& m,
                                const Vec3& wo, int) {
        return t.global ? ps::radianceEstimate(maps.global, y, m, wo, opt.globalEstimate) : Color(0.0f);
    };
    return g;
}

}  // namespace

TEST_CASE("pm: the gather visitor decides each term of the camera side and where the walk ends (Eq. 8.11) [2 pts]") {
    // The Cornell spheres at 16 x 16, maps of 8000 photon paths, one camera ray per pixel from its
    // own generator, each rendered with pm's own terms and again with a visitor that keeps one term
    // only: the four add up to pm's radiance (relative 1e-5), and each is non-zero somewhere. A
    // visitor that keeps nothing gives black; one that refuses to go on past any vertex keeps what
    // the first vertex adds but its final gather (nothing behind a sphere); the global hook sees y
    // behind x.
    const ps::Scene scene = spheres();
    ps::SampleStats stats;
    ps::PhotonMaps maps;
    maps.global = ps::tracePhotonMap(scene, ps::MapKind::Global, 8000, 8, ps::testseed::seed(872), 0, stats);
    maps.caustic = ps::tracePhotonMap(scene, ps::MapKind::Caustic, 8000, 8, ps::testseed::seed(873), 0, stats);
    const ps::PmOptions pm = ps::pmOptions(scene);
    const int w = 16, h = 16;
    // One ray per pixel, and one more (pixel w * h) through the lamp's centre: at 16 x 16 the lamp is
    // a sliver of a pixel row, which no jittered ray hit at PATHSPACE_TEST_SEED 16, so the emission
    // term went unchecked there.
    ps::Vec2 lampRaster;
    REQUIRE(scene.camera.rasterPosition(Vec3(278.0f, 548.7f, 279.5f), lampRaster));
    const auto cameraRay = [&](int pixel, ps::Rng& rng) {
        rng = ps::taskRng(ps::testseed::seed(874), 0, uint32_t(pixel));
        return ps::cameraRay(scene.camera, pixel == w * h ? lampRaster : ps::jitteredRaster(pixel, w, rng), rng);
    };
    const auto radiance = [&](int pixel, const ps::PmOptions& opt) {
        ps::Rng rng;
        const ps::Ray ray = cameraRay(pixel, rng);
        return ps::LiPhotonMap(scene, ray, rng, maps, opt);
    };
    const auto with = [&](const Terms& t) {
        ps::PmOptions opt = pm;
        opt.visitor = only(t, maps, opt);
        return opt;
    };
    const char* names[4] = {"emission", "light sample", "caustic estimate", "final gather"};
    ps::PmOptions parts[4] = {with({true, false, false, false}), with({false, true, false, false}),
                              with({false, false, true, false}), with({false, false, false, true})};
    double partTotal[4] = {0, 0, 0, 0};
    ps::PmOptions nothing = with({false, false, false, false});
    ps::PmOptions noGather = pm, firstOnly = pm;
    noGather.visitor.goesOn = [&scene](const ps::WalkVertex& v) {
        return scene.materials[size_t(v.sp.material)].isDelta();
    };
    firstOnly.visitor.goesOn = [](const ps::WalkVertex&) { return false; };
    int badGlobal = 0;
    ps::PmOptions seeing = pm;
    seeing.visitor.global = [&](const ps::SurfacePoint& x, int xBounces, const ps::SurfacePoint& y,
                                const ps::Material& m, const Vec3& wo, int yBounces) {
        if (yBounces <= xBounces || y.p == x.p) ++badGlobal;
        return ps::radianceEstimate(maps.global, y, m, wo, pm.globalEstimate);
    };
    int failures = 0, specularPixels = 0;
    for (int pixel = 0; pixel <= w * h; ++pixel) {
        const Color full = radiance(pixel, pm);
        Color sum(0.0f), part[4];
        for (int k = 0; k < 4; ++k) {
            part[k] = radiance(pixel, parts[k]);
            sum += part[k];
            partTotal[k] += ps::testrender::sum(part[k]);
        }
        const double tol = 1e-5 * (ps::testrender::sum(full) + 1e-6);
        const bool adds = std::abs(ps::testrender::sum(sum - full)) <= 3 * tol;
        if (!adds && ++failures <= 3)
            CHECK_MESSAGE(adds, "pixel " << pixel << ": pm gives " << str(full)
                                         << ", its four terms kept one at a time " << str(part[0]) << " + "
                                         << str(part[1]) << " + " << str(part[2]) << " + " << str(part[3]) << " = "
                                         << str(sum)
                                         << " (is every hook asked, and the light sample drawn either way?)");
        const Color black = radiance(pixel, nothing);
        CHECK_MESSAGE(ps::testrender::sum(black) == 0.0,
                      "pixel " << pixel << ": a visitor that keeps no term gives " << str(black));
        const Color direct = part[0] + part[1] + part[2];
        const Color kept = radiance(pixel, noGather);
        CHECK_MESSAGE(std::abs(ps::testrender::sum(kept - direct)) <= 3 * tol,
                      "pixel " << pixel << ": the walk may not go on to x's final gather, got " << str(kept)
                               << ", expected pm without its final gather " << str(direct));
        // Past no vertex: a specular first surface (not a light) ends the walk with nothing; a
        // non-specular one adds all of pm's terms but the final gather.
        ps::Rng rng;
        ps::Ray ray = cameraRay(pixel, rng);
        ps::SurfacePoint sp;
        const bool specularFirst = scene.intersect(ray, sp) && scene.materials[size_t(sp.material)].isDelta();
        if (specularFirst) {
            REQUIRE(sp.light < 0);
            ++specularPixels;
        }
        const Color first = radiance(pixel, firstOnly);
        CHECK_MESSAGE(std::abs(ps::testrender::sum(first - (specularFirst ? Color(0.0f) : direct))) <= 3 * tol,
                      "pixel " << pixel << ": the walk may go on past no vertex, got " << str(first) << ", expected "
                               << (specularFirst ? "black (its first surface is specular)"
                                                 : "pm without its final gather " + str(direct)));
        const Color seen = radiance(pixel, seeing);
        CHECK_MESSAGE(ps::testrender::sum(seen) == ps::testrender::sum(full),
                      "pixel " << pixel << ": pm's own global estimate through the hook gives " << str(seen) << ", pm "
                               << str(full));
    }
    CHECK_MESSAGE(failures == 0,
                  failures << " of " << w * h + 1 << " camera rays: the terms kept one at a time do not add up");
    CHECK_MESSAGE(specularPixels > 5, "the test needs pixels that see a sphere (" << specularPixels << ")");
    CHECK_MESSAGE(badGlobal == 0, badGlobal << " global estimates asked at y with no bounce after x");
    for (int k = 0; k < 4; ++k)
        CHECK_MESSAGE(partTotal[k] > 0.0, "the " << names[k] << " alone renders black (the test needs every term)");
}
