// Lesson 4, graded: a pixel measured as <W_e^(j), L> (Eq. 4.7) with directions that have nothing
// to do with the camera (uniform in a cone around the pixel) equals the path tracer's pixel,
// which samples W_e^(j) cos exactly (Eq. 4.8). The path tracer's pixels are lesson 3's stored
// reference of the Cornell box at 32 x 32, maxdepth 8 (tests/03-path-tracing/data/
// cornell-box-32.pfm and its variance: 262144 spp of pt, lessons/03-path-tracing/README.md has
// the command). The radiance along the sampled directions comes from lesson 3's LiMIS.
#include "lesson04.h"
#include "seed.h"

using namespace lesson04;

namespace {

void checkPixel(int px, int py, int n, uint64_t seed) {
    const ps::Scene scene = loadSceneAt("scenes/cornell-box.scene", 32, 32);
    const ps::Image ref = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32.pfm"));
    const ps::Image refVar = ps::readPFM(sourcePath("tests/03-path-tracing/data/cornell-box-32-variance.pfm"));
    const ps::Camera& cam = scene.camera;
    // The cone around the pixel's centre direction through its corners, 10 % wider (so that
    // W_e^(j) must be 0 for some of the directions).
    const ImagePlane p = planeOf(cam);
    const glm::dvec2 c = p.ofRaster(px + 0.5, py + 0.5);
    const glm::dvec3 axis = p.dir(c.x, c.y);
    double oneMinusCosMax = 0.0;
    for (int k = 0; k < 4; ++k) {
        const glm::dvec2 q = p.ofRaster(px + (k & 1), py + (k >> 1));
        const glm::dvec3 d = axis - p.dir(q.x, q.y);
        oneMinusCosMax = std::max(oneMinusCosMax, 0.5 * glm::dot(d, d));
    }
    oneMinusCosMax *= 1.1;
    const double pdf = 1.0 / (2.0 * 3.14159265358979323846 * oneMinusCosMax);
    ps::stats::Welford w;
    int bad = 0, inside = 0;
    for (int i = 0; i < n; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(seed), 0, uint32_t(i));
        const double u1 = rng.uniformDouble(), u2 = rng.uniformDouble();
        const Vec3 dir(sampleCone(u1, u2, oneMinusCosMax, axis));
        const Color s = ps::pixelMeasurementSample(scene, px, py, dir, float(pdf), rng, scene.settings.maxDepth);
        if (!ps::isFinite(s)) {
            ++bad;
            continue;
        }
        if (!ps::isBlack(s)) ++inside;
        w.add(sum(s));
    }
    const Color r = ref.at(px, py), rv = refVar.at(px, py);
    const double expected = sum(r);
    // Variance of R + G + B of the reference, bounded above (channels perfectly correlated).
    const double refSd = std::sqrt(double(rv.r)) + std::sqrt(double(rv.g)) + std::sqrt(double(rv.b));
    const double se = w.stdError(), z = std::abs(w.mean - expected) / std::sqrt(se * se + refSd * refSd);
    const double pValue = ps::stats::normalTwoSided(z);
    const bool powered = se <= 0.004 * expected;
    CHECK_MESSAGE(bad == 0, "pixel (" << px << ", " << py << "): expected 0 NaN or Inf samples, got " << bad);
    CHECK_MESSAGE(
        (pValue >= alpha() && powered),
        "Cornell box (32 x 32, maxdepth 8), pixel ("
            << px << ", " << py << "), " << n << " directions uniform in a cone around the pixel (" << inside
            << " of them gave a non-zero sample): expected the path-traced pixel, R + G + B = " << num(expected)
            << " +- " << num(refSd) << ", got <W_e^(j), L> = " << num(w.mean) << " +- " << num(se)
            << " (z = " << num(z, 4) << ", p = " << num(pValue, 3) << ", alpha = " << num(alpha(), 3) << ")"
            << std::string(powered ? "" : "; standard error above 0.4 % of the expected value: too noisy to tell"));
}

}  // namespace

TEST_CASE("measurement: <W_e, L> of the centre pixel equals the path tracer's pixel (z-test) [1 pt]") {
    checkPixel(16, 16, 200000, 4101);
}

TEST_CASE("measurement: <W_e, L> of pixels near the corners equals the path tracer's pixels (z-test) [2 pts]") {
    // 23 degrees off the axis: cos^4 = 0.72 there; one power of cos too many or too few is 8 %.
    checkPixel(2, 29, 200000, 4102);
    checkPixel(29, 29, 200000, 4103);
}
