// Lesson 7, graded: the subpaths survive by the material (Eq. 7.1a), from their first bounce on.
// The oracle is analytic: in a closed box whose diffuse walls and mirror sphere share one largest
// reflectance a, and whose glass sphere loses nothing, every non-glass vertex of a subpath is left
// with the same probability a, whatever the path did before; so the number N of non-glass
// vertices after y_0 (or z_0) is geometric from the first one on, P(N = n) = a^(n-1) (1 - a), for
// the light and the camera subpath alike (a chi-square test each). Beside it, exact checks of
// each step: no subpath ends at the glass, and a survivor's throughput is the previous one times
// the sample's weight (the albedo, at a diffuse or mirror vertex) divided by q.
#include <algorithm>
#include "lesson07.h"
#include "seed.h"

using namespace lesson07;

namespace {

// The closed box [-1, 1]^3, every face diffuse with reflectance (0.25, 0.6, 0.4) (largest channel
// 0.6; the mean is 0.42) and the ceiling emitting; a mirror sphere of reflectance 0.6 and a glass
// sphere of index 1.5 on the floor; the camera inside. No Phong: its sample can fail below the
// surface, which would end a walk for a reason the oracle does not count.
constexpr float kA = 0.6f;
const char* const kBox = R"(camera eye 0 0 -0.9  target 0 -0.2 0  up 0 1 0  fov 80  resolution 16 16
material wall   diffuse albedo 0.25 0.6 0.4
material chrome mirror albedo 0.6 0.6 0.6
material glass  dielectric ior 1.5
quad -1 -1 -1  -1 -1  1   1 -1  1   1 -1 -1  material wall
quad -1  1 -1   1  1 -1   1  1  1  -1  1  1  material wall emission 1 1 1
quad -1 -1 -1  -1  1 -1  -1  1  1  -1 -1  1  material wall
quad  1 -1 -1   1 -1  1   1  1  1   1  1 -1  material wall
quad -1 -1 -1   1 -1 -1   1  1 -1  -1  1 -1  material wall
quad -1 -1  1  -1  1  1   1  1  1   1 -1  1  material wall
sphere center -0.45 -0.6 0.3  radius 0.4  material chrome
sphere center 0.4 -0.55 0.1  radius 0.45  material glass
render spp 1 maxdepth 200
)";

// maxdepth 200: with at most 0.6 per non-glass vertex, a walk reaches it with probability ~1e-30.
constexpr int kMaxDepth = 200;
constexpr int kSubpaths = 20000;

struct Lengths {
    std::vector<double> counts;  // counts[n - 1]: subpaths with n non-glass vertices after the first
    int subpaths = 0, endedAtGlass = 0, wrongBeta = 0, betaChecked = 0, glassVertices = 0;
    std::string firstWrongBeta;
};

// Records one subpath (its vertices 1 .. size - 1).
void record(const ps::Scene& scene, const ps::Subpath& path, const char* name, Lengths& out) {
    int n = 0;
    for (size_t i = 1; i < path.size(); ++i) {
        const ps::Material& m = scene.materials[path[i].sp.material];
        const bool glass = m.kind == ps::BSDFKind::Dielectric;
        if (glass) {
            ++out.glassVertices;
            if (i + 1 == path.size()) ++out.endedAtGlass;
            continue;
        }
        ++n;
        if (i + 1 < path.size()) {
            // Diffuse and mirror: the sample's weight is the albedo exactly; the survivor divides by q = a.
            const Color want = path[i].beta * m.albedo / kA;
            const Color got = path[i + 1].beta;
            ++out.betaChecked;
            bool ok = true;
            for (int c = 0; c < 3; ++c) ok = ok && std::abs(got[c] - want[c]) <= 1e-4f * std::abs(want[c]) + 1e-30f;
            if (!ok && out.wrongBeta++ == 0)
                out.firstWrongBeta = std::string(name) + "_" + std::to_string(i + 1) + ".beta = " + str(got) +
                                     ", expected " + str(want) + " (" + name + "_" + std::to_string(i) +
                                     ".beta times the weight of the diffuse or mirror sample there, the albedo " +
                                     str(m.albedo) + ", divided by that vertex's q, Eq. 3.10 and 7.1a)";
        }
    }
    ++out.subpaths;
    if (n >= 1) {
        if (size_t(n) > out.counts.size()) out.counts.resize(size_t(n), 0.0);
        out.counts[size_t(n) - 1] += 1.0;
    }
}

void checkGeometric(const Lengths& l, const char* which) {
    INFO(which);
    REQUIRE_MESSAGE(l.subpaths == kSubpaths, "not every subpath was recorded");
    double recorded = 0.0;
    for (double c : l.counts) recorded += c;
    REQUIRE_MESSAGE(recorded >= 0.99 * kSubpaths,
                    "only " << recorded << " of " << kSubpaths << " " << which
                            << "s reached a surface after their first vertex in a closed box: are they done?");
    CHECK_MESSAGE(l.glassVertices >= kSubpaths / 50, "only " << l.glassVertices << " glass vertices in " << kSubpaths
                                                             << " " << which
                                                             << "s (the test's scene should make thousands)");
    CHECK_MESSAGE(l.endedAtGlass == 0, l.endedAtGlass << " of " << kSubpaths << " " << which
                                                      << "s ended at a glass (dielectric) vertex: the walk can "
                                                         "always leave glass, so its q decided it (Eq. 7.1a)");
    CHECK_MESSAGE(l.betaChecked > kSubpaths / 2, "only " << l.betaChecked << " survivors to check in " << which << "s");
    CHECK_MESSAGE(l.wrongBeta == 0, l.wrongBeta << " of " << l.betaChecked
                                                << " survivors carry a wrong throughput; first: " << l.firstWrongBeta);
    // P(N = n) = a^(n-1) (1 - a), the tail n > K in the last cell.
    const size_t cells = std::max<size_t>(l.counts.size(), 12) + 1;
    std::vector<double> observed(cells, 0.0), expected(cells, 0.0);
    for (size_t k = 0; k < l.counts.size(); ++k) observed[k] = l.counts[k];
    double left = 1.0;
    for (size_t k = 0; k + 1 < cells; ++k) {
        const double p = std::pow(double(kA), double(k)) * (1.0 - kA);
        expected[k] = recorded * p;
        left -= p;
    }
    expected[cells - 1] = recorded * std::max(left, 0.0);
    const ps::stats::ChiSquareResult r = ps::stats::chiSquare(observed, expected, alpha());
    std::ostringstream table;
    for (size_t k = 0; k < std::min<size_t>(cells - 1, 8); ++k)
        table << "\n  N = " << k + 1 << ": " << observed[k] << " subpaths, expected " << num(expected[k], 1);
    CHECK_MESSAGE(r.passed, which << "s: the number N of non-glass vertices after the first vertex is not geometric "
                                     "with the box's survival probability (every surface here but the glass has "
                                     "largest reflectance channel "
                                  << kA << "; Eq. 7.1a, from the first bounce on): " << r.report << table.str());
}

}  // namespace

TEST_CASE(
    "subpaths survive by the material from the first bounce: geometric lengths in a closed box, light and "
    "camera (chi-square) [2 pts]") {
    ps::Scene scene = ps::parseScene(kBox, "test_survival.cpp's box");
    // A dielectric's albedo is a field its BSDF never reads (the loader sets it to 1): 0.5 here, so
    // that a q read from it instead of from the kind of material shows.
    for (ps::Material& m : scene.materials)
        if (m.kind == ps::BSDFKind::Dielectric) m.albedo = Color(0.5f);
    Lengths light, camera;
    ps::Subpath path;
    for (int i = 0; i < kSubpaths; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(7401), 0, uint32_t(i));
        ps::lightSubpath(scene, rng, kMaxDepth, ps::Heuristic::Power, path);
        record(scene, path, "y", light);
        const Vec2 raster(rng.uniform() * 16.0f, rng.uniform() * 16.0f);
        ps::cameraSubpath(scene, rng, raster, kMaxDepth, ps::Heuristic::Power, path);
        record(scene, path, "z", camera);
    }
    checkGeometric(light, "light subpath");
    checkGeometric(camera, "camera subpath");
}
