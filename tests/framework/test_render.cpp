// Tests of framework/render.h and integrator.h: the progressive loop (sample count, time
// budget), thread-count independence, NaN/Inf accounting.
#include <doctest/doctest.h>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>
#include "eyelight.h"
#include "render.h"
#include "scene_loader.h"

using namespace ps;

namespace {

// The Cornell box, at 40 x 40 pixels so that renders take milliseconds.
Scene smallCornellBox() {
    Scene s = loadScene(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/cornell-box.scene");
    s.camera = Camera(Vec3(278, 273, -800), Vec3(278, 273, -799), Vec3(0, 1, 0), 39.3f, 40, 40);
    s.finalize();
    return s;
}

bool sameBits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), sizeof(Color) * a.pixels.size()) == 0;
}

RenderOptions options(int spp, int threads, double seconds = 0.0) {
    RenderOptions o;
    o.spp = spp;
    o.threads = threads;
    o.seconds = seconds;
    o.seed = 1234;
    return o;
}

// Records which iterations were rendered; optionally sleeps in each (a slow integrator).
class RecordingIntegrator : public EyeLight {
public:
    explicit RecordingIntegrator(int sleepMs = 0) : sleepMs_(sleepMs) {}
    void renderIteration(const Scene& scene, uint32_t iteration, uint64_t seed, Image& out,
                         SampleStats& stats) override {
        iterations.push_back(iteration);
        if (sleepMs_ > 0) std::this_thread::sleep_for(std::chrono::milliseconds(sleepMs_));
        EyeLight::renderIteration(scene, iteration, seed, out, stats);
    }
    std::vector<uint32_t> iterations;

private:
    int sleepMs_;
};

// Returns NaN (in one channel) for about 15 % of the samples, +-Inf for about 10 %, and
// otherwise a value k/256 (exact in float and double); counts what it returned.
class BadSampleIntegrator : public PixelIntegrator {
public:
    Color Li(const Scene&, const Ray&, Rng& rng) const override {
        const float u = rng.uniform();
        const int channel = int(rng.uniform() * 3.0f);
        if (u < 0.15f) {
            ++nanReturned;
            Color c(0.5f);
            c[channel] = std::numeric_limits<float>::quiet_NaN();
            return c;
        }
        if (u > 0.9f) {
            ++infReturned;
            Color c(0.5f);
            c[channel] = (u > 0.95f ? 1.0f : -1.0f) * std::numeric_limits<float>::infinity();
            return c;
        }
        const float v = std::floor(u * 256.0f) / 256.0f;
        std::lock_guard<std::mutex> lock(mutex_);
        finiteSum += 3.0 * v;
        return Color(v);
    }
    mutable std::atomic<uint64_t> nanReturned{0}, infReturned{0};
    mutable double finiteSum = 0.0;

private:
    mutable std::mutex mutex_;
};

}  // namespace

TEST_CASE("render: eyelight images are bit-identical for 1 and 2 threads") {
    const Scene scene = smallCornellBox();
    EyeLight a, b;
    const RenderResult r1 = render(scene, a, options(4, 1));
    const RenderResult r2 = render(scene, b, options(4, 2));
    const Image m1 = r1.film.mean(), m2 = r2.film.mean();
    double sum = 0.0;
    for (const Color& c : m1.pixels) sum += c.r + c.g + c.b;
    REQUIRE_MESSAGE(sum > 0.0, "the image is black: the comparison would be meaningless");
    CHECK_MESSAGE(sameBits(m1, m2), "film mean differs between 1 and 2 threads");
    CHECK_MESSAGE(sameBits(r1.film.varianceOfMean(), r2.film.varianceOfMean()),
                  "variance differs between 1 and 2 threads");
    CHECK(r1.stats.rays == r2.stats.rays);
    CHECK(r1.stats.rays == 4u * 40u * 40u);  // eyelight: one ray per pixel per iteration
    // A different seed gives a different image (the jitter changes), so the seed is used.
    EyeLight c;
    RenderOptions o = options(4, 2);
    o.seed = 99;
    CHECK_FALSE(sameBits(m1, render(scene, c, o).film.mean()));
}

TEST_CASE("render: a sample count stops after exactly that many iterations") {
    const Scene scene = smallCornellBox();
    for (int spp : {1, 3, 7}) {
        RecordingIntegrator integ;
        const RenderResult r = render(scene, integ, options(spp, 2));
        std::vector<uint32_t> expect(spp);
        for (int i = 0; i < spp; ++i) expect[i] = uint32_t(i);
        CHECK_MESSAGE(r.iterations == spp, "expected " << spp << " iterations, got " << r.iterations);
        CHECK(r.film.iterations() == spp);
        CHECK_MESSAGE(integ.iterations == expect, "iterations rendered: expected 0.."
                                                      << spp - 1 << ", got " << integ.iterations.size() << " of them");
    }
    // Neither a sample count nor a time budget: nothing is rendered.
    RecordingIntegrator none;
    const RenderResult r0 = render(scene, none, options(0, 2));
    CHECK(r0.iterations == 0);
    CHECK(none.iterations.empty());
    // Both: whichever comes first (here the sample count).
    RecordingIntegrator both;
    CHECK(render(scene, both, options(2, 2, 100.0)).iterations == 2);
}

TEST_CASE("render: a time budget stops the loop") {
    // Iterations of >= 20 ms and a budget of 0.1 s: the loop starts an iteration only while
    // the elapsed time is below the budget, so it runs 1 to 5 iterations, and reports at least
    // the budget. (The upper bound on wall time is generous: 2 s, against a stuck loop.)
    const Scene scene = smallCornellBox();
    RecordingIntegrator slow(20);
    const auto t0 = std::chrono::steady_clock::now();
    const RenderResult r = render(scene, slow, options(0, 2, 0.1));
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    CHECK_MESSAGE((r.iterations >= 1 && r.iterations <= 5),
                  "expected 1 to 5 iterations of 20 ms in 0.1 s, got " << r.iterations);
    CHECK(r.film.iterations() == r.iterations);
    CHECK_MESSAGE(r.seconds >= 0.1, "expected the reported time to reach the budget 0.1 s, got " << r.seconds);
    CHECK_MESSAGE(wall < 2.0, "the render took " << wall << " s for a budget of 0.1 s");
}

TEST_CASE("render: on the CPU clock, time the process does not compute is not counted") {
    // Five iterations that each sleep 20 ms, on one thread: 0.1 s of wall-clock time, but a
    // few ms of CPU time (40 x 40 eyelight pixels). --clock cpu must count the latter.
    const Scene scene = smallCornellBox();
    RecordingIntegrator wall(20), cpu(20);
    const RenderResult rw = render(scene, wall, options(5, 1));
    RenderOptions o = options(5, 1);
    o.clock = TimeClock::Cpu;
    const RenderResult rc = render(scene, cpu, o);
    CHECK_MESSAGE(rw.seconds >= 0.1, "wall clock: expected at least the 0.1 s slept, got " << rw.seconds);
    CHECK_MESSAGE(rc.seconds < 0.05, "CPU clock: expected a few ms (the 0.1 s slept is no CPU time), got "
                                         << rc.seconds << " s; is the render timed on the wall clock?");
    CHECK_MESSAGE(summaryLine(rc).find(" CPU s (") != std::string::npos, "summary: " << summaryLine(rc));
}

TEST_CASE("render: NaN and Inf samples are counted exactly and kept out of the image") {
    const Scene scene = smallCornellBox();
    for (int threads : {1, 2}) {
        BadSampleIntegrator integ;
        const RenderResult r = render(scene, integ, options(3, threads));
        INFO(threads << " thread(s)");
        REQUIRE(integ.nanReturned > 0);
        REQUIRE(integ.infReturned > 0);
        CHECK_MESSAGE(r.stats.nan == integ.nanReturned,
                      "expected " << integ.nanReturned << " NaN samples counted, got " << r.stats.nan);
        CHECK_MESSAGE(r.stats.inf == integ.infReturned,
                      "expected " << integ.infReturned << " Inf samples counted, got " << r.stats.inf);
        const Image m = r.film.mean(), v = r.film.varianceOfMean();
        int nonFinite = 0;
        double sum = 0.0;
        for (size_t i = 0; i < m.pixels.size(); ++i) {
            nonFinite += !isFinite(m.pixels[i]) + !isFinite(v.pixels[i]);
            sum += double(m.pixels[i].r) + m.pixels[i].g + m.pixels[i].b;
        }
        CHECK_MESSAGE(nonFinite == 0, nonFinite << " pixels of the mean or variance are NaN or Inf");
        // Bad samples enter as 0: the image holds exactly the finite values (to float rounding
        // of the 3-iteration means: relative 1e-6).
        CHECK_MESSAGE(sum * 3.0 == doctest::Approx(integ.finiteSum).epsilon(1e-6),
                      "sum of the image times 3 iterations: expected " << integ.finiteSum << ", got " << sum * 3.0);
        const std::string line = summaryLine(r);
        CHECK_MESSAGE(line.find(std::to_string(r.stats.nan) + " NaN") != std::string::npos, "summary: " << line);
        CHECK_MESSAGE(line.find(std::to_string(r.stats.inf) + " Inf") != std::string::npos, "summary: " << line);
    }
}
