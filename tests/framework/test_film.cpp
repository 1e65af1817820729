// Tests of framework/image.h and film.h: PFM and .hdr files, NaN/Inf counting, the film's
// mean and variance, deterministic splatting.
#include <doctest/doctest.h>
#include <omp.h>
#if defined(_WIN32)
#include <process.h>
#define getpid _getpid
#else
#include <unistd.h>
#endif
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include "errors.h"
#include "film.h"
#include "file_writer.h"
#include "image.h"
#include "rng.h"
#include <tinyexr.h>

using namespace ps;
namespace fs = std::filesystem;

namespace {

// A fresh file name in the system's temporary folder (tests may run in parallel processes).
std::string tempPath(const std::string& name) {
    return (fs::temp_directory_path() / ("pathspace-test-" + std::to_string(::getpid()) + "-" + name)).string();
}

bool sameBits(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), sizeof(Color) * a.pixels.size()) == 0;
}

void writeText(const std::string& path, const std::string& text) {
    std::ofstream f(path, std::ios::binary);
    f << text;
}

// The message of the InputError that f throws ("" if it throws none).
template <class F>
std::string inputErrorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) { return e.what(); }
    return "";
}

}  // namespace

TEST_CASE("film: PFM write/read round trip is bit-exact") {
    // Odd sizes (rows are stored bottom to top), negative, tiny (denormal), huge, signed zero,
    // infinite and NaN values: PFM stores raw floats, so every bit must come back.
    const float specials[] = {-1.5f,
                              0.0f,
                              -0.0f,
                              1e-40f,
                              std::numeric_limits<float>::denorm_min(),
                              std::numeric_limits<float>::min(),
                              std::numeric_limits<float>::max(),
                              -3e38f,
                              1e30f,
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              std::numeric_limits<float>::quiet_NaN(),
                              0.1f,
                              12345.678f};
    for (const std::pair<int, int>& size : {std::pair<int, int>{7, 3}, {1, 1}, {3, 7}, {13, 1}}) {
        const int w = size.first, h = size.second;  // named, not bound: clang < 16 captures no binding in a lambda
        Image img(w, h);
        Rng rng(uint64_t(w * 100 + h));
        int k = 0;
        for (Color& c : img.pixels)
            for (int ch = 0; ch < 3; ++ch)
                c[ch] = (k++ % 3 == 0) ? specials[rng.nextU32() % 14] : (rng.uniform() - 0.5f) * 1e3f;
        img.at(0, 0) = Color(1, 2, 3);  // mark the corners: a flipped image would not match
        img.at(w - 1, h - 1) = Color(-4, -5, -6);
        const std::string path = tempPath("roundtrip-" + std::to_string(w) + "x" + std::to_string(h) + ".pfm");
        writePFM(path, img);
        const Image back = readPFM(path);
        fs::remove(path);
        INFO(w << "x" << h);
        CHECK(back.width == w);
        CHECK(back.height == h);
        CHECK_MESSAGE(sameBits(img, back), "the pixels read back differ from those written");
        CHECK(back.at(0, 0) == img.at(0, 0));
    }
    // writeImage / readImage choose PFM by extension.
    Image img(5, 2, Color(0.25f, -1.0f, 3.0f));
    const std::string path = tempPath("by-extension.PFM");
    writeImage(path, img);
    CHECK(sameBits(img, readImage(path)));
    fs::remove(path);
}

TEST_CASE("film: EXR output holds the pixels exactly (32-bit float RGB, read back with tinyexr)") {
    // The renderer only writes EXR; tinyexr's own reader is the oracle here. Finite values only:
    // LoadEXR returns RGBA, top row first, like Image.
    for (const std::pair<int, int>& size : {std::pair<int, int>{7, 3}, {1, 1}, {3, 7}}) {
        const int w = size.first, h = size.second;  // named, not bound: clang < 16 captures no binding in a lambda
        Image img(w, h);
        Rng rng(uint64_t(w * 10 + h));
        for (Color& c : img.pixels)
            for (int ch = 0; ch < 3; ++ch) c[ch] = (rng.uniform() - 0.25f) * 1e3f;
        img.at(0, 0) = Color(1e-30f, 3e38f, -0.0f);
        img.at(w - 1, h - 1) = Color(-4, -5, -6);
        const std::string path = tempPath("exr-" + std::to_string(w) + "x" + std::to_string(h) + ".EXR");
        writeImage(path, img);
        float* rgba = nullptr;
        int bw = 0, bh = 0;
        const char* err = nullptr;
        const int rc = LoadEXR(&rgba, &bw, &bh, path.c_str(), &err);
        fs::remove(path);
        REQUIRE_MESSAGE(rc == TINYEXR_SUCCESS, (err ? err : "LoadEXR failed"));
        INFO(w << "x" << h);
        CHECK(bw == w);
        CHECK(bh == h);
        bool same = bw == w && bh == h;
        for (int i = 0; same && i < w * h; ++i)
            for (int ch = 0; ch < 3; ++ch)
                same = same && std::memcmp(&rgba[4 * i + ch], &img.pixels[size_t(i)][ch], sizeof(float)) == 0;
        std::free(rgba);
        CHECK_MESSAGE(same, "the pixels read back differ from those written");
    }
    Image img(2, 2);
    CHECK_THROWS_WITH_AS(writeEXR("/nonexistent-folder/x.exr", img),
                         doctest::Contains("/nonexistent-folder/x.exr: cannot open for writing"), InputError);
}

TEST_CASE("film: a reader given the expected size refuses another one from the header, before the pixels") {
    // A reference is read with the size of the render it is compared with: a file of another
    // size is refused before its pixels are allocated or decoded (issue 31: a 50 MB run-length
    // .hdr described 9.4 GB of pixels, all decoded before the size was compared).
    const Image img(3, 2, Color(0.25f));
    for (const char* ext : {".pfm", ".hdr"}) {
        const std::string path = tempPath(std::string("sized") + ext);
        writeImage(path, img);
        CHECK(readImage(path, 3, 2).width == 3);
        CHECK_THROWS_WITH_AS(readImage(path, 2, 3), doctest::Contains("the image is 3x2 pixels, expected 2x3"),
                             InputError);
        CHECK(readImage(path).height == 2);  // without an expected size: any
        fs::remove(path);
    }
}

TEST_CASE("film: every writer reports a full device, naming the file (checked to the close)") {
    // /dev/full takes no byte: every write fails with ENOSPC. A small image sits in the stream's
    // buffer until the close, so only a check of the flush and the close sees it (stb's and
    // tinyexr's own file writers check neither; issue 31 found them silent).
    if (!fs::exists("/dev/full")) {
        MESSAGE("no /dev/full on this system: skipped");
        return;
    }
    const Image img(2, 2, Color(0.5f));
    const std::string full = "/dev/full";
    const char* const nospace = "/dev/full: write failed (No space left on device)";
    CHECK_THROWS_WITH_AS(writePFM(full, img), doctest::Contains(nospace), InputError);
    CHECK_THROWS_WITH_AS(writePNG(full, img), doctest::Contains(nospace), InputError);
    CHECK_THROWS_WITH_AS(writeHDR(full, img), doctest::Contains(nospace), InputError);
    CHECK_THROWS_WITH_AS(writeEXR(full, img), doctest::Contains(nospace), InputError);
    CHECK_THROWS_WITH_AS(writeFile(full, "a line\n"), doctest::Contains(nospace), InputError);
    FileStream log(full);
    log << "iteration,spp\n0,1\n";
    CHECK_THROWS_WITH_AS(log.close(), doctest::Contains(nospace), InputError);
    // And the same writer succeeds on a file.
    const std::string path = tempPath("written.pfm");
    writePFM(path, img);
    const Image back = readPFM(path);
    fs::remove(path);
    CHECK((back.width == 2 && back.height == 2 && back.pixels == img.pixels));
}

TEST_CASE("film: readPFM of a missing or malformed file throws InputError naming the file") {
    const std::string missing = tempPath("does-not-exist.pfm");
    const std::string msg = inputErrorOf([&] { readPFM(missing); });
    CHECK_MESSAGE(msg.find(missing) != std::string::npos, "message '" << msg << "' should name " << missing);
    struct Bad {
        const char* name;
        std::string text;
    };
    const Bad bad[] = {{"wrong-magic.pfm", "P6\n2 2\n255\n"},
                       {"grey.pfm", "Pf\n2 2\n-1.0\n" + std::string(16, '\0')},
                       {"negative-size.pfm", "PF\n-3 2\n-1.0\n"},
                       {"zero-scale.pfm", "PF\n2 2\n0\n" + std::string(48, '\0')},
                       {"no-size.pfm", "PF\nabc\n"},
                       {"truncated.pfm", "PF\n2 2\n-1.0\n" + std::string(40, '\0')},  // 48 bytes needed
                       {"empty.pfm", ""}};
    for (const Bad& b : bad) {
        const std::string path = tempPath(b.name);
        writeText(path, b.text);
        const std::string m = inputErrorOf([&] { readPFM(path); });
        fs::remove(path);
        CHECK_MESSAGE(m.find(path) != std::string::npos,
                      b.name << ": expected an InputError naming the file, got '" << m << "'");
    }
}

TEST_CASE("film: hostile PFM and .hdr files give an InputError at once (no hang, no huge allocation)") {
    // Each file lies about its size or its run lengths. The readers check every size against
    // the bytes the file has before allocating, and every run length while decoding: a 24-byte
    // PFM claiming 65536 x 65536 pixels must not ask for 48 GiB, a run of length 0 must not
    // loop forever (ctest's timeout would catch a hang), a 0 x 0 image is an error.
    const std::string rle = std::string("\x02\x02\x00\x10", 4);  // RLE scanline header, width 16
    struct Bad {
        const char* name;
        std::string text;
        const char* words;
    };
    const Bad bad[] = {
        {"huge.pfm", "PF\n65536 65536\n-1.0\n" + std::string(6, '\0'), "only"},
        {"huge.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 65536 +X 65536\n" + std::string(8, '\0'), "too short"},
        {"zero.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 0 +X 0\n", "size"},
        {"zero-run.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 16\n" + rle + std::string(16, '\0'),
         "length 0"},
        {"long-run.hdr",
         "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 16\n" + rle + std::string("\xff\x01", 2) +
             std::string(14, '\x01'),
         "past the end"},
        {"truncated-rle.hdr",
         "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 16\n" + rle + std::string(4 * 17, '\x10') + rle +
             std::string("\x90\x01", 2),
         "ends"},  // scanline 0 whole, scanline 1 cut
        {"no-header-end.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", "header"},
        {"not-hdr.hdr", "P6\n2 2\n255\n", "RADIANCE"},
        {"flipped.hdr", "#?RADIANCE\n\n+Y 2 +X 2\n" + std::string(16, '\0'), "orientation"},
    };
    for (const Bad& b : bad) {
        const std::string path = tempPath(b.name);
        writeText(path, b.text);
        const std::string m = inputErrorOf([&] { readImage(path); });
        fs::remove(path);
        CHECK_MESSAGE(m.find(path) != std::string::npos,
                      b.name << ": expected an InputError naming the file, got '" << m << "'");
        CHECK_MESSAGE(m.find(b.words) != std::string::npos,
                      b.name << ": expected '" << b.words << "' in '" << m << "'");
    }
}

TEST_CASE("film: .hdr round trip is within RGBE's error") {
    // stb writes RGBE: a shared exponent e with 2^(e-1) <= max channel < 2^e and 8-bit mantissas
    // truncated, so each decoded channel satisfies 0 <= original - decoded < 2^e / 256 <=
    // max channel / 128. Widths 7 (plain scanlines) and 37 (run-length encoded, 8 <= w < 32768).
    for (auto [w, h] : {std::pair<int, int>{7, 3}, {37, 5}}) {
        Image img(w, h);
        Rng rng{uint64_t(w)};
        for (Color& c : img.pixels) {
            const float scale = std::pow(10.0f, -3.0f + 6.0f * rng.uniform());
            c = scale * Color{rng.uniform(), rng.uniform(), rng.uniform()};
        }
        for (int x = 0; x < std::min(w, 12); ++x) img.at(x, 1) = Color(2.0f, 2.0f, 0.5f);  // a run for RLE
        const std::string path = tempPath("roundtrip-" + std::to_string(w) + ".hdr");
        writeImage(path, img);
        const Image back = readImage(path);
        fs::remove(path);
        REQUIRE(back.width == w);
        REQUIRE(back.height == h);
        int bad = 0;
        for (size_t i = 0; i < img.pixels.size(); ++i) {
            const Color& o = img.pixels[i];
            const float maxC = maxComponent(o);
            for (int ch = 0; ch < 3; ++ch) {
                const float err = o[ch] - back.pixels[i][ch];
                if (!(err >= 0.0f && err < maxC / 128.0f) && ++bad <= 3)
                    FAIL_CHECK(w << "x" << h << " pixel " << i << " channel " << ch << ": wrote " << o[ch] << ", read "
                                 << back.pixels[i][ch] << " (allowed error [0, " << maxC / 128.0f << "))");
            }
        }
        CHECK(bad == 0);
    }
}

TEST_CASE("film: checkSample counts NaN and Inf separately and returns 0 for them") {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    SampleStats st;
    CHECK(checkSample(Color(1, 2, 3), st) == Color(1, 2, 3));
    CHECK(checkSample(Color(-1e30f, 0, 1e-40f), st) == Color(-1e30f, 0, 1e-40f));  // finite: unchanged
    CHECK(st.nan == 0);
    CHECK(st.inf == 0);
    CHECK(checkSample(Color(nan, 1, 1), st) == Color(0.0f));
    CHECK(checkSample(Color(1, 1, nan), st) == Color(0.0f));
    CHECK(checkSample(Color(inf, 1, 1), st) == Color(0.0f));
    CHECK(checkSample(Color(1, -inf, 1), st) == Color(0.0f));
    CHECK(checkSample(Color(1, 1, inf), st) == Color(0.0f));
    CHECK(checkSample(Color(nan, inf, 0), st) == Color(0.0f));  // both: counted once, as NaN
    CHECK_MESSAGE(st.nan == 3, "expected 3 NaN samples, got " << st.nan);
    CHECK_MESSAGE(st.inf == 3, "expected 3 Inf samples, got " << st.inf);
    CHECK(st.bad() == 6);
    SampleStats other;
    other.nan = 10;
    other.inf = 20;
    other.rays = 5;
    st += other;
    CHECK(st.nan == 13);
    CHECK(st.inf == 23);
    CHECK(st.rays == 5);
}

TEST_CASE("film: mean and variance of the mean against hand-computed values") {
    // Pixel 0 gets 1, 2, 3, 4 (red), 10, 10, 10, 10 (green), 0, 0, 0, 8 (blue); pixel 1 gets
    // 1e4 + {1, 2, 3, 4} (red: offset must not hurt), 0 elsewhere.
    // Mean: 2.5, 10, 2; 10002.5. Sample variance s^2 = sum (x - mean)^2 / (n - 1):
    // {1,2,3,4}: 5 / 3, /4 -> 5/12; constant: 0; {0,0,0,8}: (3*4 + 36) / 3 = 16, /4 -> 4.
    Film film(2, 1);
    CHECK(film.mean().pixels[0] == Color(0.0f));  // no iterations: black
    CHECK(film.varianceOfMean().pixels[0] == Color(0.0f));
    const float r0[] = {1, 2, 3, 4}, b0[] = {0, 0, 0, 8};
    for (int i = 0; i < 4; ++i) {
        Image it(2, 1);
        it.at(0, 0) = Color(r0[i], 10.0f, b0[i]);
        it.at(1, 0) = Color(1e4f + r0[i], 0.0f, 0.0f);
        film.addIteration(it);
        if (i == 0) CHECK(film.varianceOfMean().pixels[0] == Color(0.0f));  // n = 1: no estimate, 0
    }
    CHECK(film.iterations() == 4);
    const Image m = film.mean(), v = film.varianceOfMean();
    CHECK(m.at(0, 0).r == doctest::Approx(2.5));
    CHECK(m.at(0, 0).g == doctest::Approx(10.0));
    CHECK(m.at(0, 0).b == doctest::Approx(2.0));
    CHECK(m.at(1, 0).r == doctest::Approx(10002.5));
    CHECK_MESSAGE(v.at(0, 0).r == doctest::Approx(5.0 / 12.0).epsilon(1e-6), "expected 5/12, got " << v.at(0, 0).r);
    CHECK_MESSAGE(v.at(0, 0).g == 0.0f, "constant samples: expected variance 0, got " << v.at(0, 0).g);
    CHECK_MESSAGE(v.at(0, 0).b == doctest::Approx(4.0).epsilon(1e-6), "expected 4, got " << v.at(0, 0).b);
    CHECK_MESSAGE(v.at(1, 0).r == doctest::Approx(5.0 / 12.0).epsilon(1e-4),
                  "offset 1e4: expected 5/12, got " << v.at(1, 0).r);
}

namespace {
// Splats of `tasks` tasks, filled by an OpenMP loop with the given number of threads, resolved
// into an image. Task k makes 50 splats at positions and values from taskRng(3, 0, k), some
// NaN or Inf, some outside the image.
Image splatImage(int threads, size_t tasks, SampleStats& total) {
    const int w = 31, h = 17;
    SplatBuffer buf(w, h, tasks);
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    uint64_t nan = 0, inf = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : nan, inf)
    for (long k = 0; k < long(tasks); ++k) {
        SampleStats st;
        Rng rng = taskRng(3, 0, uint32_t(k));
        for (int i = 0; i < 50; ++i) {
            const Vec2 raster{rng.uniform() * (w + 2) - 1.0f, rng.uniform() * (h + 2) - 1.0f};
            Color c{rng.uniform(), rng.uniform() * 1e-3f, rng.uniform() * 1e3f};
            const uint32_t r = rng.nextU32() % 1000;
            if (r == 0) c.r = std::numeric_limits<float>::quiet_NaN();
            if (r == 1) c.g = std::numeric_limits<float>::infinity();
            buf.splat(size_t(k), raster, c, st);
        }
        nan += st.nan;
        inf += st.inf;
    }
    omp_set_num_threads(saved);
    total.nan += nan;
    total.inf += inf;
    Image img(w, h);
    buf.resolve(img);
    return img;
}
}  // namespace

TEST_CASE("film: SplatBuffer images are bit-identical for 1 and 2 threads") {
    // Float addition is not associative: only the fixed (task) order of resolve() makes the
    // sums independent of which thread filled which list.
    SampleStats s1, s2, s2b;
    const Image one = splatImage(1, 2000, s1), two = splatImage(2, 2000, s2), twoAgain = splatImage(2, 2000, s2b);
    CHECK_MESSAGE(sameBits(one, two), "1 and 2 threads gave different images");
    CHECK(sameBits(two, twoAgain));
    CHECK(s1.nan == s2.nan);
    CHECK(s1.inf == s2.inf);
    CHECK(s1.nan > 0);  // the NaN/Inf splats were counted, not added
    CHECK(s1.inf > 0);
    int nonFinite = 0;
    double sum = 0.0;
    for (const Color& c : one.pixels) {
        nonFinite += !isFinite(c);
        sum += c.b;
    }
    CHECK(nonFinite == 0);
    CHECK(sum > 0.0);
}

TEST_CASE("film: SplatBuffer adds splats inside the image and drops those outside") {
    // Inside [0, w) x [0, h): added to the pixel floor(x), floor(y); exactly on the far edge
    // (x = w, a rounding of a point on the border): the last pixel; anywhere else (left of,
    // above, right of, below the image by any amount, or NaN): dropped, not piled onto a border.
    SplatBuffer buf(4, 3, 2);
    SampleStats st;
    buf.splat(1, Vec2(1.5f, 2.5f), Color(1.0f), st);
    buf.splat(0, Vec2(0.0f, 0.0f), Color(2.0f), st);
    buf.splat(0, Vec2(4.0f, 3.0f), Color(8.0f), st);  // on the far corner: last pixel
    const Vec2 outside[] = {Vec2(-0.5f, 1.0f),
                            Vec2(1.0f, -0.25f),
                            Vec2(-1e-7f, 0.5f),
                            Vec2(4.5f, 1.0f),
                            Vec2(100.0f, 1.0f),
                            Vec2(1.0f, 3.5f),
                            Vec2(2.0f, 1e9f),
                            Vec2(std::numeric_limits<float>::quiet_NaN(), 1.0f),
                            Vec2(1.0f, std::numeric_limits<float>::infinity())};
    for (const Vec2& x : outside) buf.splat(0, x, Color(100.0f), st);
    Image img(4, 3);
    buf.resolve(img);
    CHECK(img.at(1, 2) == Color(1.0f));
    CHECK(img.at(0, 0) == Color(2.0f));
    CHECK(img.at(3, 2) == Color(8.0f));
    double total = 0.0;
    for (const Color& c : img.pixels) total += c.r;
    CHECK_MESSAGE(total == 11.0, "expected only the 3 splats inside (sum 11), got a sum of "
                                     << total << ": splats outside the image landed on border pixels");
    CHECK(st.bad() == 0);
    // Resolving empties the lists: a second resolve adds nothing.
    buf.resolve(img);
    CHECK(img.at(1, 2) == Color(1.0f));
}
