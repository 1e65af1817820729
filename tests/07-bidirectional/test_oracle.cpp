// Lesson 7, graded: the MIS weights are exactly the balance / power heuristic of the techniques'
// path densities (Eq. 7.5), with lesson 6's pdfTechnique (Eq. 6.7-6.12) as the oracle. On every
// valid connection of random pixel samples (your subpaths and connect), on Cornell-family scenes
// with a mirror sphere, a glass sphere of index 1.6, an area light, a point light and a
// background light, the weight of the technique that made the path, misWeightFull and
// misWeightRecursive, balance and power, must equal
//     w_s = p_s^b / sum_{s'} p_{s'}^b,   p_{s'} = pdfTechnique(scene, x, s') (lesson 6),
// to a relative 1e-3 (+ 1e-6 absolute for weights near 0; the densities are floats, the weights
// of long paths through glass are products of a dozen of them).
//
// The oracle is lesson 6 AS LINKED: the grader builds the lesson under test from the submission
// and every other lesson from the reference, so when lesson 7 is graded, pdfTechnique is the
// reference's (in a local build with your own lesson 6 as well, it is yours: then a failure here
// may be lesson 6's; `ctest -L lesson-06` tells). The sum-to-1 tests (test_mis.cpp) cannot see a
// density that is wrong in the same way in every technique; this one can: an area conversion
// without |cos|, a light origin without the light-selection probability, balance where power is
// asked, a specular vertex's density stored as 0 and counted as 1 (Eq. 7.7a), pdfLight where
// pdfCamera is meant (the pool), pdfBSDF's arguments swapped all fail here.
#include <tuple>
#include "lesson07.h"
#include "seed.h"

using namespace lesson07;

namespace {

// Open box (the background enters through the top and the front), a diffuse area light 10 cm
// under the opening, a point light, a mirror sphere and a glass sphere (index 1.6).
const char* kOpenBox = R"(
camera eye 278 273 -800  target 278 273 -799  up 0 1 0  fov 39.3  resolution 16 16
material white diffuse albedo 0.73 0.73 0.73
material red   diffuse albedo 0.63 0.065 0.05
material green diffuse albedo 0.14 0.45 0.091
material chrome mirror albedo 0.9 0.9 0.9
material glass  dielectric ior 1.6
quad 552.8 0 0    0 0 0    0 0 559.2    549.6 0 559.2        material white
quad 549.6 0 559.2  0 0 559.2  0 548.8 559.2  556 548.8 559.2  material white
quad 0 0 559.2  0 0 0  0 548.8 0  0 548.8 559.2          material green
quad 552.8 0 0  549.6 0 559.2  556 548.8 559.2  556 548.8 0  material red
quad 343 448.7 227  343 448.7 332  213 448.7 332  213 448.7 227  emission 17 12 4
pointlight position 150 400 400  intensity 20000 20000 20000
background radiance 0.05 0.06 0.08
sphere center 370 100 350  radius 100  material chrome
sphere center 185 100 170  radius 100  material glass
render maxdepth 6
)";

// The closed Cornell box with its ceiling light, a point light and the two spheres: paths that
// bounce around the glass from the inside (total internal reflection, two refractions).
const char* kClosedBox = R"(
camera eye 278 273 -800  target 278 273 -799  up 0 1 0  fov 39.3  resolution 16 16
material white diffuse albedo 0.73 0.73 0.73
material red   diffuse albedo 0.63 0.065 0.05
material green diffuse albedo 0.14 0.45 0.091
material chrome mirror albedo 1 1 1
material glass  dielectric ior 1.6
quad 552.8 0 0    0 0 0    0 0 559.2    549.6 0 559.2        material white
quad 556 548.8 0  556 548.8 559.2  0 548.8 559.2  0 548.8 0  material white
quad 549.6 0 559.2  0 0 559.2  0 548.8 559.2  556 548.8 559.2  material white
quad 0 0 559.2  0 0 0  0 548.8 0  0 548.8 559.2          material green
quad 552.8 0 0  549.6 0 559.2  556 548.8 559.2  556 548.8 0  material red
quad 343 548.7 227  343 548.7 332  213 548.7 332  213 548.7 227  emission 17 12 4
pointlight position 400 450 150  intensity 40000 40000 40000
sphere center 370 100 350  radius 100  material chrome
sphere center 185 130 170  radius 130  material glass
render maxdepth 7
)";

// A pool: the closed box with a flat glass surface (index 1.6) 8 cm above the floor, normal up,
// so the floor and the feet of the walls lie "inside the glass". A sphere cannot show the
// refraction's eta^2 Jacobian (pdfCamera vs pdfLight, Eq. 6.11): its two refractions are always
// on the same side of every connection and their Jacobians cancel (equal chord angles); here a
// diffuse vertex sits between two refractions, so techniques differ by (eta_L / eta_C)^2.
const char* kPool = R"(
camera eye 278 273 -800  target 278 273 -799  up 0 1 0  fov 39.3  resolution 16 16
material white diffuse albedo 0.73 0.73 0.73
material red   diffuse albedo 0.63 0.065 0.05
material green diffuse albedo 0.14 0.45 0.091
material chrome mirror albedo 1 1 1
material glass  dielectric ior 1.6
quad 552.8 0 0    0 0 0    0 0 559.2    549.6 0 559.2        material white
quad 556 548.8 0  556 548.8 559.2  0 548.8 559.2  0 548.8 0  material white
quad 549.6 0 559.2  0 0 559.2  0 548.8 559.2  556 548.8 559.2  material white
quad 0 0 559.2  0 0 0  0 548.8 0  0 548.8 559.2          material green
quad 552.8 0 0  549.6 0 559.2  556 548.8 559.2  556 548.8 0  material red
quad 343 548.7 227  343 548.7 332  213 548.7 332  213 548.7 227  emission 17 12 4
pointlight position 400 450 150  intensity 40000 40000 40000
quad 549 80 1  1 80 1  1 80 558  549 80 558  material glass
sphere center 370 100 350  radius 100  material chrome
render maxdepth 6
)";

constexpr int kSamples = 800;  // pixel samples per scene
constexpr double kRelTol = 1e-3, kAbsTol = 1e-6;

struct Case {
    std::string what;                                       // the path and technique
    double student = 0.0, oracle = 0.0, oracleOther = 0.0;  // oracleOther: the other heuristic
    bool specular = false, multiLightScene = false;
};

std::string hint(const Case& c) {
    if (std::abs(c.student - c.oracleOther) <= kRelTol * c.oracleOther + kAbsTol)
        return " It equals the OTHER heuristic's weight (" + num(c.oracleOther, 7) +
               "): balance (b = 1) and power (b = 2) swapped?";
    std::string h = " Hints:";
    if (c.specular)
        h += " the path has a specular vertex: its densities must be the lobe's coefficients from deltaLobe "
             "(pdfLight walking with the light, pdfCamera against it) converted to area with |cos| / d^2 "
             "(Eq. 7.7a), not 0 counted as 1;";
    h += " every area density needs |cos theta| / d^2 at the vertex it lands on (Eq. 7.3);"
         " the light's origin density includes the light-selection probability P(l) (Eq. 7.3);"
         " pdfBSDF(m, n, towards the previous vertex, towards the next) on both subpaths (the Lambertian pdf is the"
         " cosine of the direction sampled: swapped arguments give another number);"
         " s = 1 uses the vertex it sampled (c.sampledLight).";
    return h;
}

void checkScene(const char* name, const char* text, uint64_t seed) {
    const ps::Scene scene = ps::parseScene(text, name);
    const int w = scene.camera.width(), ht = scene.camera.height();
    const int maxDepth = scene.settings.maxDepth;
    int checked = 0, specularPaths = 0, pointPaths = 0, backgroundPaths = 0, skipped = 0;
    for (const ps::Heuristic h : {ps::Heuristic::Balance, ps::Heuristic::Power}) {
        const double b = h == ps::Heuristic::Power ? 2.0 : 1.0, bOther = 3.0 - b;
        Case worstFull, worstRec;
        double errFull = -1.0, errRec = -1.0;
        ps::Subpath camera, light;
        for (int i = 0; i < kSamples; ++i) {
            ps::Rng rng(seed, uint64_t(i));
            const Vec2 raster{rng.uniform() * float(w), rng.uniform() * float(ht)};
            ps::cameraSubpath(scene, rng, raster, maxDepth, h, camera);
            ps::lightSubpath(scene, rng, maxDepth, h, light);
            for (int t = 1; t <= int(camera.size()); ++t)
                for (int s = 0; s <= std::max(int(light.size()), 1); ++s) {
                    if (s + t < 2 || (t == 1 && s == 0) || s + t - 2 > maxDepth) continue;
                    if (s > int(light.size()) && !(s == 1 && t >= 2)) continue;
                    const float uLight = rng.uniform();
                    const Vec2 uPoint = rng.uniform2();
                    const ps::Connection c = ps::connect(scene, light, camera, s, t, uLight, uPoint);
                    if (!c.valid) continue;
                    const PathVertex* y = s == 1 ? &c.sampledLight : light.data();
                    const int n = s + t;
                    // One vertex type: the joined path is a lesson 6 path as it is.
                    ps::Path joined;
                    for (int k = 0; k < s; ++k) joined.push_back(y[k]);
                    for (int k = t - 1; k >= 0; --k) joined.push_back(camera[size_t(k)]);
                    const ps::Path& x = joined;
                    std::vector<double> p(size_t(n) + 1);
                    for (int sp = 0; sp <= n; ++sp) p[size_t(sp)] = ps::pdfTechnique(scene, x, sp);
                    if (!(p[size_t(s)] > 0.0) || !std::isfinite(p[size_t(s)])) {
                        ++skipped;  // lesson 6 says technique s cannot make this path (counted below)
                        continue;
                    }
                    double sum = 0.0, sumOther = 0.0;
                    for (const double q : p) {
                        sum += std::pow(q, b);
                        sumOther += std::pow(q, bOther);
                    }
                    Case cs;
                    cs.oracle = std::pow(p[size_t(s)], b) / sum;
                    cs.oracleOther = std::pow(p[size_t(s)], bOther) / sumOther;
                    bool spec = false;
                    for (const PathVertex& v : joined) spec = spec || v.specular;
                    cs.specular = spec;
                    if (h == ps::Heuristic::Balance) {
                        ++checked;
                        specularPaths += spec;
                        pointPaths += joined[0].pointLight;
                        backgroundPaths += joined[0].infinite;
                    }
                    JoinedPath jp;
                    jp.x = joined;
                    jp.s = s;
                    jp.t = t;
                    cs.what = describe(jp);
                    const double wf = ps::misWeightFull(y, s, camera.data(), t, c.rev, h);
                    const double wr = ps::misWeightRecursive(y, s, camera.data(), t, c.rev, h);
                    const double tol = kRelTol * cs.oracle + kAbsTol;
                    const double ef = std::isfinite(wf) ? std::abs(wf - cs.oracle) / tol : 1e30;
                    const double er = std::isfinite(wr) ? std::abs(wr - cs.oracle) / tol : 1e30;
                    if (ef > errFull) {
                        errFull = ef;
                        worstFull = cs;
                        worstFull.student = wf;
                    }
                    if (er > errRec) {
                        errRec = er;
                        worstRec = cs;
                        worstRec.student = wr;
                    }
                }
        }
        const std::string hs = h == ps::Heuristic::Power ? "power" : "balance";
        for (const auto& worst :
             {std::tuple<double, const Case&, const char*>{errFull, worstFull, "misWeightFull"},
              std::tuple<double, const Case&, const char*>{errRec, worstRec, "misWeightRecursive"}}) {
            // named, not bound: clang < 16 captures no binding in a lambda
            const double err = std::get<0>(worst);
            const Case& c = std::get<1>(worst);
            const char* form = std::get<2>(worst);
            CHECK_MESSAGE(err <= 1.0, name << ", " << hs << " heuristic, " << form
                                           << ": expected the weight p_s^b / sum p_s'^b of lesson 6's pdfTechnique "
                                              "(relative 1e-3), worst on "
                                           << c.what << ": expected " << num(c.oracle, 7) << ", got "
                                           << num(c.student, 7) << " (ratio " << num(c.student / c.oracle, 5) << ")."
                                           << hint(c));
        }
    }
    CHECK_MESSAGE(checked >= 300, name << ": expected at least 300 valid connections from " << kSamples
                                       << " pixel samples (your subpaths and connect), got " << checked);
    CHECK_MESSAGE(specularPaths >= 20,
                  name << ": expected at least 20 connected paths through the mirror or the glass, got "
                       << specularPaths << " (are the subpaths stopped at specular vertices?)");
    CHECK_MESSAGE(pointPaths >= 20,
                  name << ": expected at least 20 connected paths from the point light, got " << pointPaths);
    if (scene.background >= 0)
        CHECK_MESSAGE(backgroundPaths >= 20,
                      name << ": expected at least 20 connected paths from the background, got " << backgroundPaths);
    // A connection that lesson 6 says its own technique cannot make (p_s = 0) is a bug in the
    // subpaths or in connect (a connection at a specular vertex, a background joined to the
    // pinhole) -- or a path through the point where a sphere touches the floor: on a segment a
    // fraction of a millimetre long the directions between the stored float positions miss
    // Snell's law by more than deltaLobe's 1e-3, and lesson 6 gives every technique p = 0. Those
    // are about 0.2 % of the connections in the closed box; a bug gives many more.
    CHECK_MESSAGE(skipped <= checked / 200, name << ": " << skipped << " of " << checked + skipped
                                                 << " valid connections have p_s = 0 under lesson 6's pdfTechnique: "
                                                    "connect made a path its technique cannot sample (Eq. 7.7)");
}

}  // namespace

TEST_CASE(
    "MIS weights equal the balance and power heuristics of lesson 6's path pdfs, through mirror and glass, from area, point and background lights [4 pts]") {
    checkScene("open box (area, point and background light, mirror, glass 1.6)", kOpenBox, ps::testseed::seed(7101));
    checkScene("closed box (area and point light, mirror, glass 1.6)", kClosedBox, ps::testseed::seed(7102));
    checkScene("pool (area and point light, mirror, a glass surface 1.6 over the floor)", kPool,
               ps::testseed::seed(7103));
}
