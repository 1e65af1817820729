// Lesson 8, graded: Ward's irradiance cache (Eq. 8.15-8.18).
// Exact: the weight of a record (Eq. 8.16) against the formula; the interpolation (Eq. 8.17) of
// a synthetic cache (records on a floor and a wall, tilted normals, records the point is behind)
// against the test's own sum, and at a record's own point its own value. Statistical (z-tests at
// level alpha(), lesson08.h, Bonferroni over the points inside the test): a new record's E and R
// (Eq. 8.18) at five surface points of the Cornell box against the test's own gather of 64 x 64
// cosine-distributed directions into the same global map. Counted: the cache of the Cornell box
// holds more records as the error bound a tightens (Ward: about 1 / a^2 of them).
#include <omp.h>
#include <functional>
#include <unordered_map>
#include <limits>
#include "lesson08.h"
#include "scene_text.h"
#include "warps.h"

using namespace lesson08;
using ps::IrradianceCache;
using ps::IrradianceRecord;

namespace {

IrradianceRecord record(const Vec3& p, const Vec3& n, float R, const Color& E) {
    IrradianceRecord r;
    r.p = p;
    r.n = glm::normalize(n);
    r.R = R;
    r.E = E;
    return r;
}

// Ward's weight in double, and the classic mistakes, for the messages.
double wardWeight(const IrradianceRecord& r, const Vec3& x, const Vec3& n) {
    const double d = glm::length(ps::Vec3(x - r.p)), c = std::max(0.0, 1.0 - double(glm::dot(n, r.n)));
    const double e = d / r.R + std::sqrt(c);
    return e > 0.0 ? 1.0 / e : std::numeric_limits<double>::infinity();
}

std::string weightHint(const IrradianceRecord& r, const Vec3& x, const Vec3& n, double got) {
    const double d = glm::length(ps::Vec3(x - r.p)), c = std::max(0.0, 1.0 - double(glm::dot(n, r.n)));
    auto near = [&](double v) { return std::isfinite(v) && std::abs(got - v) <= 1e-4 * std::abs(v); };
    if ((d == 0.0 && std::isinf(got)) || near(r.R / d)) return " (no normal term: the sqrt(1 - n . n_i) is missing)";
    if (near(1.0 / (d / r.R + c))) return " (1 - n . n_i without its square root)";
    if (near(1.0 / (d * d / (double(r.R) * r.R) + std::sqrt(c)))) return " (the squared distance divided by R^2)";
    if (near(1.0 / (d * r.R + std::sqrt(c)))) return " (the distance times R, not divided by it)";
    if (near(d / r.R + std::sqrt(c))) return " (the error itself, not its inverse)";
    return "";
}

// The test's own Eq. 8.17 (double), with switches for the classic mistakes.
struct Interpolated {
    bool found = false;
    ps::Color E;
};
Interpolated oracle(const IrradianceCache& cache, const Vec3& x, const Vec3& n, bool normalTerm = true,
                    bool behindTest = true) {
    double sw = 0.0, s[3] = {0.0, 0.0, 0.0};
    for (const IrradianceRecord& r : cache.records) {
        if (behindTest && glm::dot(x - r.p, 0.5f * (n + r.n)) < -ps::kCacheBehindTolerance * r.R) continue;
        double w = wardWeight(r, x, n);
        if (!normalTerm) w = double(r.R) / glm::length(ps::Vec3(x - r.p));
        if (!(w > 1.0 / cache.a)) continue;
        if (std::isinf(w)) return {true, r.E};
        sw += w;
        for (int c = 0; c < 3; ++c) s[c] += w * r.E[c];
    }
    if (sw == 0.0) return {};
    return {true, ps::Color(float(s[0] / sw), float(s[1] / sw), float(s[2] / sw))};
}

bool close(const ps::Color& a, const ps::Color& b) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(a[c] - b[c]) > 1e-5f * std::max(1.0f, std::abs(b[c]))) return false;
    return true;
}

// The k-nearest box estimate of Eq. 8.6 over a photon map, the test's own (a uniform grid of
// cells of the maximum radius, every candidate's distance, nth_element), so that the oracle of a
// record's E does not run the lesson's radianceEstimate or its kd-tree.
struct OwnEstimate {
    const PhotonMap& map;
    float cell;
    std::unordered_map<uint64_t, std::vector<size_t>> grid;
    OwnEstimate(const PhotonMap& m, float maxRadius) : map(m), cell(maxRadius) {
        for (size_t i = 1; i <= map.size(); ++i) grid[key(cellOf(map.nodes[i].p))].push_back(i);
    }
    glm::ivec3 cellOf(const Vec3& p) const { return glm::ivec3(glm::floor(p / cell)); }
    static uint64_t key(const glm::ivec3& c) {
        return (uint64_t(uint32_t(c.x)) * 73856093u) ^ (uint64_t(uint32_t(c.y)) * 19349663u) ^
               (uint64_t(uint32_t(c.z)) * 83492791u);
    }
    Color operator()(const ps::SurfacePoint& sp, const ps::Material& m, const Vec3& wo, int k) const {
        std::vector<std::pair<float, size_t>> near;
        const glm::ivec3 c = cellOf(sp.p);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const glm::ivec3 q = c + glm::ivec3(dx, dy, dz);
                    const auto it = grid.find(key(q));
                    if (it == grid.end()) continue;
                    for (size_t i : it->second) {
                        if (cellOf(map.nodes[i].p) != q) continue;  // a hash collision
                        const Vec3 d = map.nodes[i].p - sp.p;
                        const float d2 = glm::dot(d, d);
                        if (d2 <= cell * cell) near.push_back({d2, i});
                    }
                }
        float r2 = cell * cell;
        if (int(near.size()) >= k) {
            std::nth_element(near.begin(), near.begin() + (k - 1), near.end());
            r2 = near[size_t(k - 1)].first;
            near.resize(size_t(k));
        }
        Color L(0.0f);
        if (!(r2 > 0.0f)) return L;
        for (const auto& n : near) {
            const Photon& ph = map.nodes[n.second];
            L += ps::evalBSDF(m, sp.n, wo, ph.wLight()) * ph.power * float(1.0 / (ps::kPi * double(r2)));
        }
        return L;
    }
};

// A point of a scene's surface, as the camera sees it through raster position (x, y).
ps::SurfacePoint seenAt(const ps::Scene& scene, float x, float y, Vec3& wo) {
    ps::Ray ray = scene.camera.generateRay(Vec2(x, y));
    ps::SurfacePoint sp;
    REQUIRE_MESSAGE(scene.intersect(ray, sp), "the camera ray through (" << x << ", " << y << ") hits nothing");
    wo = -ray.d;
    return sp;
}

}  // namespace

TEST_CASE("irradiance cache: Ward's weight from the split-sphere bound (Eq. 8.16) [1 pt]") {
    const IrradianceRecord r = record(Vec3(1, 2, 3), Vec3(0, 0, 1), 2.0f, Color(1.0f));
    struct Case {
        Vec3 x, n;
    };
    const float c60 = 0.5f, s60 = std::sqrt(0.75f);
    const Case cases[] = {
        {Vec3(2, 2, 3), Vec3(0, 0, 1)},         // 1 away, same normal: 1 / (1/2) = 2
        {Vec3(1, 2, 3), Vec3(s60, 0, c60)},     // at the record, normal turned by 60 degrees
        {Vec3(1, 2.5f, 3), Vec3(0, s60, c60)},  // both
        {Vec3(1.3f, 2.4f, 3), Vec3(0.1f, 0.2f, 0.97f)},
        {Vec3(4, 2, 3), Vec3(1, 0, 0)},  // far, perpendicular
    };
    for (const Case& c : cases) {
        const Vec3 n = glm::normalize(c.n);
        const double expected = wardWeight(r, c.x, n), got = ps::irradianceWeight(r, c.x, n);
        CHECK_MESSAGE(std::abs(got - expected) <= 1e-5 * expected,
                      "record at " << str(r.p) << ", n_i " << str(r.n) << ", R = " << r.R << "; at x = " << str(c.x)
                                   << ", n = " << str(n) << ": expected w = 1 / (|x - x_i| / R + sqrt(1 - n . n_i)) = "
                                   << num(expected) << ", got " << num(got) << weightHint(r, c.x, n, got));
    }
    const float own = ps::irradianceWeight(r, r.p, r.n);
    CHECK_MESSAGE(
        (std::isinf(own) && own > 0.0f),
        "at the record's own point and normal: expected w = +infinity (the error bound is 0), got " << num(own));
}

TEST_CASE(
    "irradiance cache: the interpolation weighs the records that cover a point, and a record's own point gets its own "
    "value (Eq. 8.17) [2 pts]") {
    // Records on the floor z = 0 (normals up, some tilted) and on the wall x = 0 (normals +x), a
    // few records just above the floor (a point of the floor is behind them), radii 0.1 ... 0.5.
    ps::Rng rng(ps::testseed::seed(851));
    IrradianceCache cache;
    cache.a = 0.3f;
    for (int i = 0; i < 60; ++i) {
        const float x = rng.uniform(), y = rng.uniform(), R = 0.1f + 0.4f * rng.uniform();
        const Color E{0.5f + rng.uniform(), 0.5f + rng.uniform(), 0.5f + rng.uniform()};
        if (i % 6 == 5) cache.records.push_back(record(Vec3(0, y, x), Vec3(1, 0, 0), R, E));           // the wall
        else if (i % 6 == 4) cache.records.push_back(record(Vec3(x, y, 0.05f), Vec3(0, 0, 1), R, E));  // above
        else if (i % 6 == 3)
            cache.records.push_back(record(Vec3(x, y, 0), Vec3(0.3f * (rng.uniform() - 0.5f), 0.2f, 1), R, E));
        else cache.records.push_back(record(Vec3(x, y, 0), Vec3(0, 0, 1), R, E));
    }
    const Vec3 up(0, 0, 1);
    int covered = 0;
    for (int q = 0; q < 300; ++q) {
        const Vec3 x = q < 200 ? Vec3{rng.uniform(), rng.uniform(), 0.0f} : Vec3{0.0f, rng.uniform(), rng.uniform()};
        const Vec3 n = q < 200 ? up : Vec3(1, 0, 0);
        const Interpolated want = oracle(cache, x, n);
        Color got(-7.0f);
        const bool found = ps::interpolateIrradiance(cache, x, n, got);
        covered += want.found;
        std::string hint;
        if (found && want.found && !close(got, want.E)) {
            const Interpolated noNormal = oracle(cache, x, n, false), noBehind = oracle(cache, x, n, true, false);
            if (noNormal.found && close(got, noNormal.E))
                hint = " (the normal term left out: records on the wall used)";
            else if (noBehind.found && close(got, noBehind.E))
                hint = " (records the point lies behind used: (x - x_i) . (n + n_i) / 2 < -0.01 R_i excludes them)";
            else hint = " (weights w_i = 1 / (|x - x_i| / R_i + sqrt(1 - n . n_i)), used where w_i > 1 / a)";
        }
        CHECK_MESSAGE(found == want.found, "query " << q << " at " << str(x) << ", n = " << str(n) << ": expected "
                                                    << (want.found ? "records that cover it" : "no record to cover it")
                                                    << " (a = " << cache.a << "), got " << (found ? "true" : "false"));
        if (!found) CHECK_MESSAGE(got == Color(-7.0f), "query " << q << ": E changed although no record covers it");
        if (found && want.found)
            CHECK_MESSAGE(close(got, want.E), "query " << q << " at " << str(x) << ", n = " << str(n)
                                                       << ": expected E = " << str(want.E) << ", got " << str(got)
                                                       << hint);
    }
    CHECK(covered > 100);  // the test's own layout: most floor points are covered
    // A case worked by hand, independent of the test's own sum above: a = 0.5 (records used where
    // w > 2), the point x = (0.25, 0, 0) with normal +y. A at the origin and B at (0.5, 0, 0), both
    // R = 1 and normal +y: w = 1 / 0.25 = 4 each; C at (2, 0, 0): w = 1 / 1.75 < 2, unused; D at
    // (0.25, 0.5, 0), R = 2, normal +y, 0.5 above the floor: x is behind it ((x - x_i) . n = -0.5 <
    // -0.01 * 2), unused although w = 1 / 0.25 = 4; E with normal +z at x itself: w = 1 / sqrt(1 -
    // 0) = 1 < 2, unused. So E(x) = (4 * 1 + 4 * 3) / 8 = 2 in every channel.
    {
        IrradianceCache hand;
        hand.a = 0.5f;
        hand.records = {record(Vec3(0, 0, 0), Vec3(0, 1, 0), 1.0f, Color(1.0f)),
                        record(Vec3(0.5f, 0, 0), Vec3(0, 1, 0), 1.0f, Color(3.0f)),
                        record(Vec3(2, 0, 0), Vec3(0, 1, 0), 1.0f, Color(100.0f)),
                        record(Vec3(0.25f, 0.5f, 0), Vec3(0, 1, 0), 2.0f, Color(200.0f)),
                        record(Vec3(0.25f, 0, 0), Vec3(0, 0, 1), 1.0f, Color(300.0f))};
        Color got(-7.0f);
        const bool found = ps::interpolateIrradiance(hand, Vec3(0.25f, 0, 0), Vec3(0, 1, 0), got);
        CHECK_MESSAGE((found && close(got, Color(2.0f))),
                      "five records worked by hand (a = 0.5; two of weight 4 with E = 1 and 3, one too far, one "
                      "the point is behind, one with a perpendicular normal): expected E = 2, got "
                          << (found ? str(got) : std::string("nothing found")));
    }
    // At a record's own point and normal its weight is infinite: its own value, not a blend.
    for (size_t i = 0; i < cache.records.size(); i += 6) {
        const IrradianceRecord& r = cache.records[i];
        Color got(-7.0f);
        const bool found = ps::interpolateIrradiance(cache, r.p, r.n, got);
        CHECK_MESSAGE((found && got == r.E), "at record " << i << "'s own point " << str(r.p)
                                                          << " and normal: expected "
                                                          << "its own E = " << str(r.E) << " exactly, got "
                                                          << (found ? str(got) : std::string("nothing found")));
    }
}

TEST_CASE(
    "irradiance cache: a new record's E is the final gather at its point, R the harmonic mean distance (Eq. 8.18, "
    "t-test) [2 pts]") {
    omp_set_num_threads(1);
    // The Cornell box with the floor's corners in the opposite order: the same image (diffuse
    // surfaces reflect on both sides), but the floor's normal points down, away from the camera,
    // so a record there must turn it to the side it is seen from.
    const std::string path = sourcePath("scenes/cornell-box.scene");
    const ps::Scene scene =
        ps::parseScene(ps::scenetext::replaceAll(ps::scenetext::withResolution(ps::scenetext::readText(path), 32, 32),
                                                 "quad 552.8 0 0    0 0 0    0 0 559.2    549.6 0 559.2",
                                                 "quad 549.6 0 559.2    0 0 559.2    0 0 0    552.8 0 0"),
                       path);
    REQUIRE(!scene.caps.hasDeltaBSDF());  // the test's own gather needs no specular bounces
    ps::SampleStats stats;
    const PhotonMap global = ps::tracePhotonMap(scene, ps::MapKind::Global, 20000, scene.settings.maxDepth,
                                                ps::testseed::seed(852), 0, stats);
    ps::PmOptions opt;
    opt.maxDepth = scene.settings.maxDepth;
    opt.globalEstimate.k = 50;
    opt.globalEstimate.maxRadius = 0.1f * scene.radius;
    opt.gatherSide = 12;
    opt.minR = 0.0f;
    opt.maxR = std::numeric_limits<float>::max();
    // Five points the camera sees (the floor, the back wall, the two side walls, the tall block);
    // at each, kRecords records against kGathers gathers of the test's own (side x side
    // cosine-distributed directions, one per stratum, each pi L from the same global map), both
    // means compared by Welch's t-test: E (r + g + b) and the mean of 1 / d (= 1 / R). The test's
    // gathers estimate the radiance at each hit with its own k-nearest box sum (OwnEstimate), not
    // with the lesson's radianceEstimate.
    const Vec2 pixels[] = {{16.5f, 30.5f}, {16.5f, 8.5f}, {1.5f, 16.5f}, {30.5f, 16.5f}, {11.5f, 14.5f}};
    constexpr int kPoints = 5, kRecords = 32, kGathers = 32, kSide = 16;
    const double level = alpha() / (2 * kPoints);  // E and R at each point (Bonferroni)
    ps::Rng rng(ps::testseed::seed(853));
    const OwnEstimate ownEstimate(global, opt.globalEstimate.maxRadius);
    REQUIRE(opt.globalEstimate.filter == ps::Filter::Box);
    int flipped = 0;
    for (int k = 0; k < kPoints; ++k) {
        Vec3 wo;
        const ps::SurfacePoint sp = seenAt(scene, pixels[k].x, pixels[k].y, wo);
        const Vec3 n = glm::dot(sp.n, wo) < 0.0f ? -sp.n : sp.n;
        flipped += n != sp.n;
        const ps::Frame frame(n);
        ps::stats::Welford E, invD, recE, recInvD;
        for (int g = 0; g < kGathers; ++g) {
            double sumL = 0.0, sumInv = 0.0;
            for (int j = 0; j < kSide; ++j)
                for (int i = 0; i < kSide; ++i) {
                    const Vec2 u{(i + rng.uniform()) / kSide, (j + rng.uniform()) / kSide};
                    ps::Ray ray = scene.spawnRay(sp, frame.toWorld(ps::sampleCosineHemisphere(u)));
                    ps::SurfacePoint y;
                    if (!scene.intersect(ray, y)) continue;
                    const ps::Material& m = scene.materials[size_t(y.material)];
                    sumL += ps::testrender::sum(ownEstimate(y, m, -ray.d, opt.globalEstimate.k));
                    sumInv += 1.0 / ray.tMax;
                }
            E.add(ps::kPi * sumL / (kSide * kSide));
            invD.add(sumInv / (kSide * kSide));
        }
        IrradianceRecord r;
        for (int g = 0; g < kRecords; ++g) {
            ps::Rng recRng(ps::testseed::seed(854) + uint64_t(k * kRecords + g));
            r = ps::irradianceRecord(scene, sp, wo, 0, recRng, global, opt);
            recE.add(ps::testrender::sum(r.E));
            recInvD.add(1.0 / double(r.R));
        }
        CHECK_MESSAGE(r.p == sp.p,
                      "point " << k << ": expected the record at the point " << str(sp.p) << ", got " << str(r.p));
        CHECK_MESSAGE(glm::dot(r.n, n) > 0.9999f, "point " << k << " " << str(sp.p) << ": expected the record's normal "
                                                           << str(n) << " (on the side it was seen from, wo's), got "
                                                           << str(r.n));
        // Welch's t-test of the two means.
        auto welch = [&](const ps::stats::Welford& a, const ps::stats::Welford& b, double& t) {
            const double va = a.variance() / double(a.n), vb = b.variance() / double(b.n);
            t = (a.mean - b.mean) / std::sqrt(va + vb);
            const double dof = (va + vb) * (va + vb) / (va * va / double(a.n - 1) + vb * vb / double(b.n - 1));
            return ps::stats::studentTwoSided(t, dof) >= level;
        };
        double tE = 0.0, tR = 0.0;
        const bool okE = welch(recE, E, tE), okR = welch(recInvD, invD, tR);
        const double ratio = recE.mean / E.mean;
        std::string hint;
        if (std::abs(ratio - 1.0 / ps::kPi) < 0.05) hint = " (a factor 1 / pi: E = pi / M * sum L)";
        else if (std::abs(ratio - ps::kPi) < 0.15) hint = " (a factor pi too large)";
        else if (recE.mean == 0.0) hint = " (black: do the gather rays leave on wo's side of the surface?)";
        CHECK_MESSAGE(okE, "point " << k << " " << str(sp.p) << ", n = " << str(n) << ": expected E_i (r + g + b) "
                                    << num(E.mean) << " (the test's gathers of " << kSide * kSide
                                    << " cosine-distributed directions), got " << num(recE.mean) << " on average over "
                                    << kRecords << " records (ratio " << num(ratio) << ", t = " << num(tE) << ", level "
                                    << num(level) << ")" << hint);
        CHECK_MESSAGE(okR, "point " << k << " " << str(sp.p) << ": expected the mean of 1 / R_i = mean of 1 / d = "
                                    << num(invD.mean) << " (R = " << num(1.0 / invD.mean) << "), got "
                                    << num(recInvD.mean) << " (t = " << num(tR)
                                    << "; R is the harmonic mean of the distances, not their mean)");
        // Power: the records' mean must be known to 2 %, or a mistake of a few % would pass.
        CHECK_MESSAGE(std::sqrt(recE.variance() / kRecords) <= 0.02 * E.mean,
                      "point " << k << ": the records' E vary too much to judge them: standard error "
                               << num(std::sqrt(recE.variance() / kRecords)) << " of " << num(E.mean));
    }
    CHECK(flipped == 1);  // the test's own layout: the floor is seen from the side its normal points away from
    // R is clamped to [minR, maxR].
    Vec3 wo;
    const ps::SurfacePoint sp = seenAt(scene, 16.5f, 28.5f, wo);
    ps::PmOptions small = opt, large = opt;
    small.gatherSide = large.gatherSide = 3;
    small.maxR = 1.0f;
    large.minR = 1e6f;
    large.maxR = 2e6f;
    ps::Rng r1(1), r2(1);
    CHECK_MESSAGE(ps::irradianceRecord(scene, sp, wo, 0, r1, global, small).R == 1.0f,
                  "maxR = 1: expected R clamped to 1");
    CHECK_MESSAGE(ps::irradianceRecord(scene, sp, wo, 0, r2, global, large).R == 1e6f,
                  "minR = 1e6: expected R clamped to 1e6");
}

TEST_CASE("irradiance cache: the number of records grows as the error bound a tightens (Eq. 8.17) [1 pt]") {
    omp_set_num_threads(1);
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 32, 32);
    ps::SampleStats stats;
    const PhotonMap global = ps::tracePhotonMap(scene, ps::MapKind::Global, 8192, scene.settings.maxDepth,
                                                ps::testseed::seed(855), 0, stats);
    ps::PmOptions opt;
    opt.maxDepth = scene.settings.maxDepth;
    opt.globalEstimate.k = 50;
    opt.globalEstimate.maxRadius = 0.1f * scene.radius;
    opt.gatherSide = 4;
    opt.minR = 0.03f * scene.radius;
    opt.maxR = 0.5f * scene.radius;
    std::vector<size_t> counts;
    std::string table;
    for (float a : {0.4f, 0.2f, 0.1f}) {
        const IrradianceCache cache =
            ps::buildIrradianceCache(scene, global, opt, a, 32, 32, ps::testseed::seed(856), 0, stats);
        counts.push_back(cache.records.size());
        table += " a = " + num(a) + ": " + std::to_string(cache.records.size());
    }
    MESSAGE("records:" << table);
    CHECK_MESSAGE((counts[0] > 0 && counts[1] >= counts[0] * 3 / 2 && counts[2] >= counts[1] * 3 / 2),
                  "the Cornell box at 32 x 32: expected at least 1.5 times as many records each time a is halved "
                  "(about 4 times while the records' reach a R_i is larger than a pixel), got"
                      << table);
}
