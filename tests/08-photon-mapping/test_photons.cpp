// Lesson 8, graded: photon tracing (Eq. 8.1-8.3) on the mirror scene (data/mirror-floor.scene,
// lesson08.h): a point light of intensity I between a diffuse floor below and a mirror facing
// down above. Exact: every stored photon carries Phi / N (Phi = 4 pi I, grey surfaces), lies on
// the floor (never on the mirror) and arrived from above. Statistical (binomial counts as z-tests
// at level alpha(), lesson08.h): the caustic map holds the photons reflected by the mirror,
// N_c * rho_m * Omega_m / (4 pi) on average; with maxdepth 2 the global map holds the floor's
// direct hits and those caustic hits, N_g (Omega_f + rho_m Omega_m) / (4 pi); and with maxdepth 1
// the power stored on the floor is the irradiance integral over the floor, I * Omega_f.
#include "lesson08.h"

using namespace lesson08;

namespace {

ps::Scene mirrorScene() { return loadSceneAt("tests/08-photon-mapping/data/mirror-floor.scene", 16, 16); }

PhotonMap trace(const ps::Scene& scene, ps::MapKind kind, int emitted, int maxDepth, uint64_t seed) {
    ps::SampleStats stats;
    PhotonMap map = ps::tracePhotonMap(scene, kind, emitted, maxDepth, seed, 0, stats);
    CHECK_MESSAGE(stats.bad() == 0, "photon tracing: " << stats.nan << " NaN and " << stats.inf << " Inf photons");
    return map;
}

// A count of a binomial(n, p) against its mean: z-test at alpha().
void checkCount(const std::string& what, double count, double n, double p) {
    const double mean = n * p, sd = std::sqrt(n * p * (1.0 - p));
    const double z = (count - mean) / sd;
    CHECK_MESSAGE(std::abs(z) <= zCritical(), what << ": expected " << num(mean) << " photons on average (sd "
                                                   << num(sd) << "), got " << count << " (z = " << num(z) << ", level "
                                                   << num(alpha()) << ")");
}

}  // namespace

TEST_CASE("photons: every stored photon carries Phi / N, on the floor, arriving from above (Eq. 8.2, 8.3) [3 pts]") {
    const ps::Scene scene = mirrorScene();
    const double Phi = 4.0 * ps::kPi * kIntensity;  // a point light's power: I times the full sphere
    for (ps::MapKind kind : {ps::MapKind::Global, ps::MapKind::Caustic}) {
        const char* name = kind == ps::MapKind::Global ? "global" : "caustic";
        const int N = 4000;
        const PhotonMap map = trace(scene, kind, N, 8, ps::testseed::seed(811));
        CHECK_MESSAGE(map.emitted == N, name << " map: emitted should be N = " << N);
        REQUIRE_MESSAGE(map.size() > 0, name << " map of " << N << " emitted photons: no photon stored");
        const double expected = Phi / N;
        int wrongPower = 0, onMirror = 0, fromBelow = 0;
        Color example(0.0f);
        for (size_t i = 1; i <= map.size(); ++i) {
            const Photon& ph = map.nodes[i];
            for (int c = 0; c < 3; ++c)
                if (std::abs(ph.power[c] - expected) > 1e-5 * expected) {
                    if (!wrongPower) example = ph.power;
                    ++wrongPower;
                    break;
                }
            if (std::abs(ph.p.y) > 1e-3f) ++onMirror;
            if (ph.wLight().y <= 0.0f) ++fromBelow;
        }
        std::string hint;
        if (wrongPower) {
            const double ratio = double(example.r) / expected;
            if (std::abs(ratio * N - 1.0) < 0.1 || std::abs(ratio - double(N)) < 0.1 * N)
                hint = " (the power is not divided by N = emitted?)";
            else if (ratio < 1.0)
                hint =
                    " (power lost at a bounce: survive with q = the largest component of the throughput from the "
                    "first bounce on, and let lightWalk divide by q; lesson 3's survivalProbability waits 3 "
                    "bounces)";
        }
        CHECK_MESSAGE(wrongPower == 0, name << " map: " << wrongPower << " of " << map.size()
                                            << " photons do not carry Phi / N = 4 pi I / N = " << num(expected)
                                            << " in every channel, e.g. " << str(example) << hint);
        CHECK_MESSAGE(onMirror == 0, name << " map: " << onMirror
                                          << " photons stored off the floor (y = 0), i.e. on the mirror: photons are "
                                             "stored at non-specular surfaces only");
        CHECK_MESSAGE(fromBelow == 0, name << " map: " << fromBelow
                                           << " photons whose wLight points down: wLight is the direction back towards "
                                              "where the photon came from (above the floor)");
    }
}

TEST_CASE("photons: the caustic map holds the L S+ D paths, the global map every diffuse hit (Eq. 8.1, 8.2) [3 pts]") {
    const ps::Scene scene = mirrorScene();
    const double omegaM = squareSolidAngle(kMirrorHalf, kLightToMirror);
    const double omegaF = squareSolidAngle(kFloorHalf, kLightToFloor);
    const int N = 20000;
    // Caustic map: a photon that goes up hits the mirror (Omega_m / 4 pi), survives its roulette
    // (rho_m) and lands on the floor inside the mirror's 3 x 3 footprint: one photon per path.
    const PhotonMap caustic = trace(scene, ps::MapKind::Caustic, N, 8, ps::testseed::seed(812));
    int outside = 0;
    for (size_t i = 1; i <= caustic.size(); ++i)
        outside += std::abs(caustic.nodes[i].p.x) > 1.5f + 1e-3f || std::abs(caustic.nodes[i].p.z) > 1.5f + 1e-3f;
    CHECK_MESSAGE(outside == 0,
                  "caustic map: " << outside
                                  << " photons outside the mirror's footprint |x|, |z| <= 1.5: only photons "
                                     "that came from the light through specular bounces alone (L S+ D)");
    checkCount("caustic map, " + std::to_string(N) +
                   " emitted (rho_m Omega_m / 4 pi = " + num(kMirrorAlbedo * omegaM / (4.0 * ps::kPi)) + ")",
               double(caustic.size()), N, kMirrorAlbedo * omegaM / (4.0 * ps::kPi));
    // Global map at maxdepth 2: the floor's direct hits and the mirror's caustic hits, each path
    // at most one photon (a bounce off the floor reaches the mirror at the second bounce, where
    // nothing is stored, and ends there).
    const PhotonMap global = trace(scene, ps::MapKind::Global, N, 2, ps::testseed::seed(813));
    checkCount("global map, maxdepth 2, " + std::to_string(N) +
                   " emitted ((Omega_f + rho_m Omega_m) / 4 pi; a specular hit stores nothing)",
               double(global.size()), N, (omegaF + kMirrorAlbedo * omegaM) / (4.0 * ps::kPi));
}

TEST_CASE("photons: the power stored on the floor is the irradiance integral I * Omega_f (Eq. 8.2) [2 pts]") {
    // Maxdepth 1: only the floor's direct hits. Their total power estimates the flux the floor
    // receives, the integral of E = I cos(theta) / d^2 over it: I times its solid angle.
    const ps::Scene scene = mirrorScene();
    const double omegaF = squareSolidAngle(kFloorHalf, kLightToFloor);
    const int N = 10000;
    const PhotonMap global = trace(scene, ps::MapKind::Global, N, 1, ps::testseed::seed(814));
    double total = 0.0;
    for (size_t i = 1; i <= global.size(); ++i) total += global.nodes[i].power.g;
    // Each photon carries Phi / N with Phi = 4 pi I: the sum is (Phi / N) * Binomial(N, p).
    const double p = omegaF / (4.0 * ps::kPi), perPhoton = 4.0 * ps::kPi * kIntensity / N;
    const double mean = kIntensity * omegaF, sd = perPhoton * std::sqrt(N * p * (1.0 - p));
    const double z = (total - mean) / sd;
    CHECK_MESSAGE(std::abs(z) <= zCritical(), "sum of the photons' power on the floor (maxdepth 1, "
                                                  << N << " emitted): expected the flux I Omega_f = " << num(mean)
                                                  << " W (sd " << num(sd) << "), got " << num(total)
                                                  << " W (z = " << num(z) << ")");
}

TEST_CASE("photons: a continuation rule given to tracePhoton reaches the photon walk (Eq. 3.10, 8.3) [1 pt]") {
    // A rule (lesson 3's continuation rule, the test's own) that splits every photon path in two at
    // its first surface, each half with beta / 2, and leaves every other vertex to photonSurvival:
    // the floor's second hits (after the mirror, maxdepth 3) then carry Phi / (2N), which no
    // photon carries without the rule (photonSurvival keeps every power at Phi / N).
    const ps::Scene scene = mirrorScene();
    const double Phi = 4.0 * ps::kPi * kIntensity;
    constexpr int N = 2000;
    ps::SampleStats stats;
    const ps::PhotonRules rules = [] {
        return ps::ContinuationRule([](const ps::WalkVertex& v, ps::Rng&) {
            return v.bounces == 1 ? ps::Continuations{2, v.beta * 0.5f} : ps::Continuations{1, v.beta};
        });
    };
    const PhotonMap map =
        ps::tracePhotonMap(scene, ps::MapKind::Global, N, 3, ps::testseed::seed(814), 0, stats, rules);
    int full = 0, half = 0, other = 0;
    for (size_t i = 1; i <= map.size(); ++i) {
        const double p = map.nodes[i].power.r;
        if (std::abs(p - Phi / N) <= 1e-4 * Phi / N) ++full;
        else if (std::abs(p - 0.5 * Phi / N) <= 1e-4 * Phi / N) ++half;
        else ++other;
    }
    CHECK_MESSAGE((full > 0 && half > 0 && other == 0),
                  "tracePhotonMap (global, maxdepth 3) with a rule that splits every photon path in two at its first "
                  "surface (beta / 2 each): expected photons of Phi / N (the first hits) and of Phi / (2N) (the "
                  "halves' hits after the mirror), got "
                      << full << " of Phi / N, " << half << " of Phi / (2N) and " << other
                      << " of another power (the rule must be the photon walk's continuation rule)");
}
