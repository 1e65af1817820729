// Tests of framework/metrics.h: MSE, relMSE (eps = 0.01) and the trimmed relMSE.
#include <doctest/doctest.h>
#include <cmath>
#include <string>
#include "errors.h"
#include "metrics.h"

using namespace ps;

TEST_CASE("metrics: MSE and relMSE of a small image, by hand") {
    // img = [(1, 2, 3), (0, 0, 0)], ref = [(1, 1, 1), (0.5, 0, 2)]: the 6 terms are
    // (x - r)^2 = 0, 1, 4, 0.25, 0, 4              -> MSE = 9.25 / 6
    // (x - r)^2 / (r^2 + 0.01) = 0, 1/1.01, 4/1.01, 0.25/0.26, 0, 4/4.01 -> relMSE = sum / 6.
    Image img(2, 1), ref(2, 1);
    img.at(0, 0) = Color(1, 2, 3);
    img.at(1, 0) = Color(0, 0, 0);
    ref.at(0, 0) = Color(1, 1, 1);
    ref.at(1, 0) = Color(0.5f, 0, 2);
    const ErrorMetrics e = computeError(img, ref);
    const double mse = 9.25 / 6.0, rel = (1.0 / 1.01 + 4.0 / 1.01 + 0.25 / 0.26 + 4.0 / 4.01) / 6.0;
    CHECK_MESSAGE(e.mse == doctest::Approx(mse).epsilon(1e-12), "MSE: expected " << mse << ", got " << e.mse);
    CHECK_MESSAGE(e.relMse == doctest::Approx(rel).epsilon(1e-7), "relMSE: expected " << rel << ", got " << e.relMse);
    // 6 terms: floor(0.006) = 0 dropped, so the trimmed value is the plain one.
    CHECK_MESSAGE(e.relMseTrimmed == doctest::Approx(rel).epsilon(1e-7),
                  "trimmed relMSE: expected " << rel << ", got " << e.relMseTrimmed);
    CHECK(kRelMseEpsilon == 0.01);
    // Against itself: all 0. Symmetric in MSE, not in relMSE.
    const ErrorMetrics self = computeError(ref, ref);
    CHECK(self.mse == 0.0);
    CHECK(self.relMse == 0.0);
    CHECK(computeError(ref, img).mse == doctest::Approx(mse).epsilon(1e-12));
    CHECK(computeError(ref, img).relMse != doctest::Approx(rel));
}

TEST_CASE("metrics: trimmed relMSE drops exactly the largest 0.1 % of the terms") {
    // 1000 pixels = 3000 terms: floor(3000 * 0.001) = 3 are dropped. The reference is 1
    // everywhere (r^2 + eps = 1.01); the image is 1 + 0.1 * sqrt(1.01) everywhere (each term
    // 0.01) except 4 terms with (x - r)^2 / 1.01 = 100, 200, 300, 400. The three largest
    // (400, 300, 200) go: trimmed = (2996 * 0.01 + 100) / 2997; plain = (2996 * 0.01 + 1000) / 3000.
    Image ref(40, 25, Color(1.0f)), img(40, 25);
    const double base = 0.1 * std::sqrt(1.01);
    for (Color& c : img.pixels) c = Color(float(1.0 + base));
    const double big[] = {100, 200, 300, 400};
    const int where[][2] = {{3, 0}, {17, 1}, {640, 2}, {999, 0}};  // pixel, channel
    for (int k = 0; k < 4; ++k) img.pixels[where[k][0]][where[k][1]] = float(1.0 + std::sqrt(big[k] * 1.01));
    // The exact terms as float stores them.
    double small = 0.0, sumBig = 0.0;
    for (size_t i = 0; i < img.pixels.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const double d = double(img.pixels[i][ch]) - 1.0, t = d * d / 1.01;
            (t > 50 ? sumBig : small) += t;
        }
    const double t100 = std::pow(double(img.pixels[3][0]) - 1.0, 2) / 1.01;
    const ErrorMetrics e = computeError(img, ref);
    const double plain = (small + sumBig) / 3000.0, trimmed = (small + t100) / 2997.0;
    CHECK_MESSAGE(e.relMse == doctest::Approx(plain).epsilon(1e-9),
                  "relMSE: expected " << plain << ", got " << e.relMse);
    CHECK_MESSAGE(e.relMseTrimmed == doctest::Approx(trimmed).epsilon(1e-9),
                  "trimmed relMSE (3 of 3000 terms dropped): expected "
                      << trimmed << ", got " << e.relMseTrimmed << " (dropping 2 would give "
                      << (small + t100 + 200) / 2998.0 << ", 4 would give " << small / 2996.0 << ")");
    // 2997 terms (999 pixels): floor(2.997) = 2 dropped.
    Image ref2(999, 1, Color(1.0f)), img2(999, 1, Color(float(1.0 + base)));
    for (int k = 0; k < 4; ++k) img2.pixels[where[k][0] % 999][where[k][1]] = float(1.0 + std::sqrt(big[k] * 1.01));
    const ErrorMetrics e2 = computeError(img2, ref2);
    double all2 = 0.0, top2 = 0.0;
    for (const Color& c : img2.pixels)
        for (int ch = 0; ch < 3; ++ch) {
            const double t = std::pow(double(c[ch]) - 1.0, 2) / 1.01;
            all2 += t;
            if (t > 250) top2 += t;  // the 300 and 400 terms
        }
    CHECK_MESSAGE(e2.relMseTrimmed == doctest::Approx((all2 - top2) / 2995.0).epsilon(1e-9),
                  "2997 terms: expected 2 dropped, got trimmed relMSE " << e2.relMseTrimmed);
}

TEST_CASE("metrics: images of different sizes throw InputError naming both sizes") {
    const Image a(4, 3), b(3, 4), c(4, 4);
    std::string msg;
    try {
        computeError(a, b);
    } catch (const InputError& e) { msg = e.what(); }
    CHECK_MESSAGE(msg.find("3x4") != std::string::npos, "message: '" << msg << "'");
    CHECK_MESSAGE(msg.find("4x3") != std::string::npos, "message: '" << msg << "'");
    CHECK_THROWS_AS(computeError(a, c), InputError);
    CHECK_NOTHROW(computeError(a, a));
    // Empty images: no terms, all metrics 0 (no division by zero).
    const ErrorMetrics e = computeError(Image(), Image());
    CHECK(e.mse == 0.0);
    CHECK(e.relMse == 0.0);
}
