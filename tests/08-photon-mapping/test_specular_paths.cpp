// Lesson 8, graded: what the Cornell scenes never show the estimators (issue 28, "reach"), each
// against an oracle of the test's own, exactly (no statistics):
//  - a lamp and the background seen in a mirror and through glass, under pm and ppm: the lamp's
//    radiance (or the background's) times the throughput of the specular bounces, traced here with
//    the framework's sampleBSDF and the same uniform numbers (every number the pieces draw is 0.5
//    or a fixed value, replayed through Rng::replayFrom);
//  - ppm at the maximum depth: nothing from a diffuse surface reached after maxdepth bounces;
//  - pm's caustic estimate at a diffuse surface seen in a mirror, against a brute-force sum over
//    the test's own photons;
//  - pm-ic: the cache only at Lambertian surfaces (a Phong surface gathers), with the normal on
//    the side the surface is seen from;
//  - the final gather through glass where the two eta^2 do not cancel (a diffuse ball inside a
//    glass ball: the gather ray refracts once), against the test's own trace;
//  - k nearest when fewer than k photons lie within the maximum radius is in test_estimate.cpp.
#include "lesson08.h"
#include "scene_text.h"

using namespace lesson08;

namespace {

// Every uniform number is `fill` (the numbers the pieces draw, in any order).
struct Constant : ps::UniformSource {
    float fill = 0.5f;
    float next() override { return fill; }
};

ps::Scene sceneOf(const std::string& text) { return ps::parseScene(text, "(test_specular_paths)"); }

using ps::testrender::specularOracle;  // tests/support/render_helpers.h

bool close(const Color& a, const Color& b, float rel = 1e-4f) {
    return glm::length(a - b) <= rel * (glm::length(b) + 1e-6f);
}

// The box estimate (Eq. 8.6, 8.7) over `photons` by brute force: the k nearest within maxRadius
// (r the k-th distance if k were found), or every photon within maxRadius if k == 0.
Color bruteForceBox(const std::vector<Photon>& photons, const ps::SurfacePoint& sp, const ps::Material& m,
                    const Vec3& wo, int k, float maxRadius) {
    std::vector<std::pair<double, size_t>> d;
    for (size_t i = 0; i < photons.size(); ++i) {
        const Vec3 v = photons[i].p - sp.p;
        d.push_back({double(glm::dot(v, v)), i});
    }
    std::sort(d.begin(), d.end());
    const double maxD2 = double(maxRadius) * maxRadius;
    size_t n = 0;
    while (n < d.size() && d[n].first <= maxD2 && (k == 0 || n < size_t(k))) ++n;
    const double r2 = (k > 0 && n == size_t(k)) ? d[n - 1].first : maxD2;
    Color L(0.0f);
    for (size_t j = 0; j < n; ++j) {
        const Photon& ph = photons[d[j].second];
        L += ps::evalBSDF(m, sp.n, wo, ph.wLight()) * ph.power * float(1.0 / (ps::kPi * r2));
    }
    return L;
}

// A photon at p arriving from direction `from` (towards where it came from), with power `power`.
Photon photonFrom(const Vec3& p, const Vec3& from, const Color& power) {
    Photon ph;
    ph.p = p;
    ph.power = power;
    ph.setWLight(glm::normalize(from));
    return ph;
}

// A mirror (albedo 0.8 0.6 0.4) at z = -2 facing the camera at the origin, a lamp (2 3 4) of
// 1 x 1 at z = 1 behind the camera facing the mirror, a background (0.25 0.5 0.75); and a glass
// ball (ior 1.5) at (0, 6, -8), above the mirror's edge, in front of a second lamp (5 4 3) at z = -10.
const char* kMirrorGlass = R"(
camera eye 0 0 0  target 0 0 -1  fov 40  resolution 4 4
material mirror mirror albedo 0.8 0.6 0.4
material glass dielectric ior 1.5
quad -1 -1 -2  1 -1 -2  1 1 -2  -1 1 -2  material mirror
quad -0.5 -0.5 1  -0.5 0.5 1  0.5 0.5 1  0.5 -0.5 1  emission 2 3 4
sphere center 0 6 -8  radius 1  material glass
quad -0.5 6.5 -10  0.5 6.5 -10  0.5 8.5 -10  -0.5 8.5 -10  emission 5 4 3
background radiance 0.25 0.5 0.75
render spp 1 maxdepth 8
)";

}  // namespace

TEST_CASE(
    "pm and ppm: a lamp and the background seen in a mirror and through glass, times the specular bounces' "
    "throughput (Eq. 8.11, 8.14) [2 pts]") {
    const ps::Scene scene = sceneOf(kMirrorGlass);
    struct View {
        Vec3 d;
        const char* what;
        bool lamp;  // the test's own layout: ends on a lamp (else the background)
    };
    // Straight at the mirror: the first lamp; tilted: past it, the background in the mirror;
    // through the centre of the glass ball (both surfaces at normal incidence): the second lamp.
    const View views[] = {{Vec3(0, 0, -1), "the lamp in the mirror", true},
                          {glm::normalize(Vec3(0.2f, 0.0f, -1.0f)), "the background in the mirror", false},
                          {glm::normalize(Vec3(0.0f, 6.0f, -8.0f)), "the lamp through the glass ball", true}};
    const ps::PhotonMaps maps;  // empty: no photon lights these views
    for (const View& view : views) {
        for (float u : {0.5f, 0.01f}) {  // 0.5: refraction at the glass; 0.01: reflection
            const ps::Ray ray(Vec3(0.0f), view.d);
            bool lamp = false;
            const Color want = specularOracle(scene, ray, u, 8, lamp);
            if (u == 0.5f) REQUIRE_MESSAGE(lamp == view.lamp, "the test's own layout: " << view.what);
            REQUIRE(!ps::isBlack(want));
            Constant numbers;
            numbers.fill = u;
            ps::Rng rng;
            rng.replayFrom(&numbers);
            ps::PmOptions opt;
            opt.maxDepth = 8;
            const Color pm = ps::LiPhotonMap(scene, ray, rng, ps::PhotonMaps{}, opt);
            CHECK_MESSAGE(close(pm, want), "LiPhotonMap, " << view.what << " (every uniform number " << u
                                                           << "): expected " << str(want)
                                                           << " (its radiance times the specular bounces' "
                                                              "throughput), got "
                                                           << str(pm));
            const Color ppm = ps::LiProgressive(scene, ray, rng, maps.global, 0.01f, 8);
            CHECK_MESSAGE(close(ppm, want), "LiProgressive, " << view.what << " (every uniform number " << u
                                                              << "): expected " << str(want) << ", got " << str(ppm));
        }
    }
}

TEST_CASE(
    "ppm and pm: a diffuse surface seen in a mirror: the estimate there, and nothing past the maximum depth "
    "(Eq. 8.11, 8.14) [1 pt]") {
    // The mirror of kMirrorGlass reflects the camera's central ray onto a white diffuse wall at
    // z = 1 (facing the mirror, no lamp), where the test puts photons of its own. No light in the
    // scene: next-event estimation adds nothing, and the global map is empty.
    const ps::Scene scene = sceneOf(R"(
camera eye 0 0 0  target 0 0 -1  fov 40  resolution 4 4
material mirror mirror albedo 0.8 0.6 0.4
material white diffuse albedo 0.7 0.7 0.7
quad -1 -1 -2  1 -1 -2  1 1 -2  -1 1 -2  material mirror
quad -3 -3 1  -3 3 1  3 3 1  3 -3 1  material white
render spp 1 maxdepth 8
)");
    const ps::Ray ray(Vec3(0.0f), Vec3(0, 0, -1));
    ps::SurfacePoint wall;
    {
        ps::Ray r(Vec3(0.0f, 0.0f, -1.9f), Vec3(0, 0, 1));
        REQUIRE(scene.intersect(r, wall));
    }
    ps::Rng gen(ps::testseed::seed(861));
    std::vector<Photon> photons;
    for (int i = 0; i < 400; ++i) {
        const float x = 0.6f * (gen.uniform() - 0.5f), y = 0.6f * (gen.uniform() - 0.5f);
        const float c = 0.5f + gen.uniform();
        photons.push_back(photonFrom(Vec3(x, y, 1.0f), Vec3(gen.uniform() - 0.5f, gen.uniform() - 0.5f, -1.0f),
                                     Color(c, 0.5f * c, 0.25f)));
    }
    PhotonMap map;
    ps::buildPhotonMap(photons, map);
    const ps::Material& white = scene.materials[size_t(wall.material)];
    const Color mirror(0.8f, 0.6f, 0.4f);
    const Vec3 wo(0, 0, -1);  // from the wall back to the mirror
    // ppm: the fixed-radius box estimate at the wall, r^2 = 0.04, after one mirror bounce.
    const Color ppmWant = mirror * bruteForceBox(photons, wall, white, wo, 0, 0.2f);
    REQUIRE(!ps::isBlack(ppmWant));
    Constant numbers;
    ps::Rng rng;
    rng.replayFrom(&numbers);
    const Color ppm = ps::LiProgressive(scene, ray, rng, map, 0.04f, 2);
    CHECK_MESSAGE(close(ppm, ppmWant),
                  "LiProgressive, maxDepth 2, a diffuse wall seen in a mirror (albedo 0.8 0.6 "
                  "0.4): expected the mirror's albedo times the box estimate there, "
                      << str(ppmWant) << ", got " << str(ppm));
    const Color ppm1 = ps::LiProgressive(scene, ray, rng, map, 0.04f, 1);
    CHECK_MESSAGE(ppm1 == Color(0.0f),
                  "LiProgressive, maxDepth 1: the wall is the path's second vertex (1 bounce "
                  "after the mirror), at the maximum depth: expected black, got "
                      << str(ppm1));
    // pm: the caustic map's k-nearest estimate at the wall (k = 30, maxRadius 0.3), after the mirror.
    ps::PmOptions opt;
    opt.maxDepth = 8;
    opt.causticEstimate.k = 30;
    opt.causticEstimate.maxRadius = 0.3f;
    ps::PhotonMaps maps;
    maps.caustic = map;
    const Color pmWant = mirror * bruteForceBox(photons, wall, white, wo, 30, 0.3f);
    const Color pm = ps::LiPhotonMap(scene, ray, rng, maps, opt);
    CHECK_MESSAGE(close(pm, pmWant),
                  "LiPhotonMap, a diffuse wall seen in a mirror, photons in the caustic map only: "
                  "expected the mirror's albedo times the caustic estimate there, "
                      << str(pmWant) << ", got " << str(pm));
}

TEST_CASE(
    "pm-ic: the cache at a Lambertian surface from either side, never at a Phong surface (Eq. 8.11, 8.17) [1 pt]") {
    // A white Lambertian floor (x < 0) and a Phong floor (x > 0) at y = 0, no light, empty photon
    // maps: the only light is the cache's, records of the test's own. Seen from above, the
    // Lambertian floor shows albedo / pi * E of the record there (normal +y); seen from below, that
    // of the record with normal -y at the same point; the Phong floor gathers (black here).
    const ps::Scene scene = sceneOf(R"(
camera eye 0 1 3  target 0 0 0  fov 40  resolution 4 4
material white diffuse albedo 0.6 0.6 0.6
material glossy phong albedo 0.6 0.6 0.6 exponent 10
quad -2 0 -2  -2 0 2  0 0 2  0 0 -2  material white
quad 0 0 -2  0 0 2  2 0 2  2 0 -2  material glossy
render spp 1 maxdepth 8
)");
    ps::IrradianceCache cache;
    cache.a = 0.3f;
    auto rec = [](const Vec3& p, const Vec3& n, const Color& E) {
        ps::IrradianceRecord r;
        r.p = p;
        r.n = n;
        r.E = E;
        r.R = 1.0f;
        return r;
    };
    const Color above(100, 200, 300), below(400, 500, 600), glossyE(700, 800, 900);
    cache.records = {rec(Vec3(-1, 0, 0), Vec3(0, 1, 0), above), rec(Vec3(-1, 0, 0), Vec3(0, -1, 0), below),
                     rec(Vec3(1, 0, 0), Vec3(0, 1, 0), glossyE)};
    ps::PmOptions opt;
    opt.maxDepth = 8;
    opt.cache = &cache;
    struct View {
        Vec3 o, d;
        Color want;
        const char* what;
    };
    const float rho = 0.6f * ps::kInvPi;
    const View views[] = {{Vec3(-1, 1, 0), Vec3(0, -1, 0), rho * above, "the Lambertian floor from above"},
                          {Vec3(-1, -1, 0), Vec3(0, 1, 0), rho * below,
                           "the Lambertian floor from below (its normal points away from the camera)"},
                          {Vec3(1, 1, 0), Vec3(0, -1, 0), Color(0.0f),
                           "the Phong floor (its record must not be used: the cache holds irradiance, which only a "
                           "Lambertian surface turns into radiance as albedo / pi * E)"}};
    for (const View& v : views) {
        Constant numbers;
        ps::Rng rng;
        rng.replayFrom(&numbers);
        const Color got = ps::LiPhotonMap(scene, ps::Ray(v.o, v.d), rng, ps::PhotonMaps{}, opt);
        CHECK_MESSAGE(close(got, v.want), "LiPhotonMap with an irradiance cache, "
                                              << v.what << ": expected " << str(v.want) << ", got " << str(got));
    }
}

TEST_CASE(
    "pm: the final gather through glass into a diffuse ball inside it (Eq. 8.11, the eta^2 that does not cancel) [1 pt]") {
    // A white ball (radius 0.5) inside a glass ball (radius 1, ior 1.5), photons of the test's own
    // on the white ball's top. The gather ray from (0, 0, 3) straight down the axis meets the
    // glass at normal incidence: it refracts into the glass (its radiance scaled by the eta^2 of
    // Transport::Radiance, which no second refraction undoes) and reaches the white ball, or
    // reflects and leaves the scene. Oracle: the test's own trace with the framework's sampleBSDF
    // and the same numbers, then the brute-force estimate at the white ball.
    const ps::Scene scene = sceneOf(R"(
camera eye 0 0 4  target 0 0 0  fov 40  resolution 4 4
material glass dielectric ior 1.5
material white diffuse albedo 0.8 0.8 0.8
sphere center 0 0 0  radius 1  material glass
sphere center 0 0 0  radius 0.5  material white
render spp 1 maxdepth 8
)");
    ps::Rng gen(ps::testseed::seed(862));
    std::vector<Photon> photons;
    for (int i = 0; i < 300; ++i) {
        const float x = 0.3f * (gen.uniform() - 0.5f), y = 0.3f * (gen.uniform() - 0.5f);
        const Vec3 p(x, y, std::sqrt(0.25f - x * x - y * y));
        photons.push_back(photonFrom(p, p + Vec3(gen.uniform() - 0.5f, 0.0f, 0.5f), Color(1.0f, 0.5f, 0.25f)));
    }
    ps::PhotonMaps maps;
    ps::buildPhotonMap(photons, maps.global);
    ps::PmOptions opt;
    opt.maxDepth = 8;
    opt.globalEstimate.k = 20;
    opt.globalEstimate.maxRadius = 0.2f;
    ps::SurfacePoint sp;
    sp.p = Vec3(0, 0, 3);
    sp.n = Vec3(0, 0, -1);
    const Vec3 wi(0, 0, -1);
    Color throughGlass(0.0f);
    for (float u : {0.5f, 0.01f}) {
        // The test's own trace: the glass, then the white ball (or nothing).
        Color want(0.0f);
        ps::Ray ray = scene.spawnRay(sp, wi);
        ps::SurfacePoint glass;
        REQUIRE(scene.intersect(ray, glass));
        const float firstHit = ray.tMax;
        ps::BSDFSample s;
        REQUIRE(ps::sampleBSDF(scene.materials[size_t(glass.material)], glass.n, -ray.d, Vec2(u, u), u,
                               ps::Transport::Radiance, s));
        ps::Ray inner = scene.spawnRay(glass, s.wi);
        ps::SurfacePoint y;
        if (scene.intersect(inner, y) && !scene.materials[size_t(y.material)].isDelta())
            want = s.weight * bruteForceBox(photons, y, scene.materials[size_t(y.material)], -inner.d, 20, 0.2f);
        if (u == 0.5f) REQUIRE_MESSAGE(!ps::isBlack(want), "the test's own layout: the gather reaches the white ball");
        Constant numbers;
        numbers.fill = u;
        ps::Rng rng;
        rng.replayFrom(&numbers);
        float d = -1.0f;
        const Color got = ps::gatherRadiance(scene, sp, wi, Color(1.0f), 0, rng, maps.global, opt, &d);
        CHECK_MESSAGE(close(got, want), "gatherRadiance from " << str(sp.p) << " straight into a glass ball (every "
                                                               << "uniform number " << u << "): expected " << str(want)
                                                               << " (the glass's sample weight in radiance transport "
                                                                  "times the estimate at the white ball), got "
                                                               << str(got));
        CHECK_MESSAGE(d == doctest::Approx(firstHit), "gatherRadiance: expected the distance to the first surface hit, "
                                                          << num(firstHit) << ", got " << num(d));
        if (u == 0.5f) throughGlass = want;
    }
    // The weight the gather ray carries from x scales what it finds; and the depth: from a vertex
    // after 0 bounces with maxDepth 1 the glass is the one surface the ray may reach.
    Constant numbers;
    numbers.fill = 0.5f;
    ps::Rng rng;
    rng.replayFrom(&numbers);
    const Color weighted = ps::gatherRadiance(scene, sp, wi, Color(0.5f, 0.25f, 1.0f), 0, rng, maps.global, opt);
    const Color wantWeighted = throughGlass * Color(0.5f, 0.25f, 1.0f);
    CHECK_MESSAGE(close(weighted, wantWeighted),
                  "gatherRadiance with weight (0.5, 0.25, 1) (every uniform number 0.5): "
                      << "expected " << str(wantWeighted) << ", got " << str(weighted));
    ps::PmOptions shallow = opt;
    shallow.maxDepth = 1;
    rng.replayFrom(&numbers);
    const Color cut = ps::gatherRadiance(scene, sp, wi, Color(1.0f), 0, rng, maps.global, shallow);
    CHECK_MESSAGE(ps::isBlack(cut), "gatherRadiance from a vertex after 0 bounces with maxDepth 1 into the glass ball: "
                                        << "expected black (the white ball would be a path's second bounce after "
                                           "that vertex), got "
                                        << str(cut));
}

TEST_CASE("kd-tree: an empty map, and k = 0, find nothing (Eq. 8.5) [1 pt]") {
    PhotonMap empty;
    ps::buildPhotonMap({}, empty);
    std::vector<ps::NearPhoton> found = {{1, 0.0f}};
    CHECK_MESSAGE(ps::nearestPhotons(empty, Vec3(0.0f), 5, 1.0f, found) == 0,
                  "nearestPhotons on an empty map: "
                  "expected 0 photons visited");
    CHECK_MESSAGE(found.empty(), "nearestPhotons on an empty map: expected nothing found");
    found = {{1, 0.0f}};
    CHECK_MESSAGE(ps::photonsInRadius(empty, Vec3(0.0f), 1.0f, found) == 0,
                  "photonsInRadius on an empty map: expected 0 photons visited");
    CHECK_MESSAGE(found.empty(), "photonsInRadius on an empty map: expected nothing found");
    PhotonMap one;
    ps::buildPhotonMap({photonAt(Vec3(0.0f))}, one);
    found.clear();
    ps::nearestPhotons(one, Vec3(0.0f), 0, 1.0f, found);
    CHECK_MESSAGE(found.empty(), "nearestPhotons with k = 0: expected nothing found, got " << found.size());
    ps::nearestPhotons(one, Vec3(0.1f), 1, 1.0f, found);
    CHECK_MESSAGE(found.size() == 1,
                  "nearestPhotons, k = 1, a map of one photon within the radius: expected it "
                  "found, got "
                      << found.size() << " photons");
    ps::photonsInRadius(one, Vec3(0.1f), 1.0f, found);
    CHECK_MESSAGE(found.size() == 1,
                  "photonsInRadius, a map of one photon within the radius: expected it found, "
                  "got "
                      << found.size() << " photons");
}
