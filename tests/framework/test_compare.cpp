// Tests of `pathspace compare`'s numbers and pictures (report/compare.h), on images whose
// answers are worked out by hand: relMSE, the mean difference and its z-score, the per-pixel z,
// the worst channels in order, NaN left out, the colours of the difference picture.
#include <doctest/doctest.h>
#include <cmath>
#include "errors.h"
#include "report/compare.h"

using namespace ps;

TEST_CASE("compare: an image against itself differs nowhere") {
    Image a(4, 3, Color(0.25f, 0.5f, 1.0f)), var(4, 3, Color(0.01f));
    const ImageComparison c = compareImages(a, a, &var, &var);
    CHECK(c.error.relMse == 0.0);
    CHECK(c.meanDifference == 0.0);
    CHECK(c.meanZ == 0.0);
    CHECK(c.beyondThreshold == 0);
    CHECK(c.channels == 36);
    double scale = 0.0;
    const Image d = differenceImage(a, a, &var, &var, 0.0, scale);
    for (const Color& p : d.pixels) CHECK(isBlack(p));
}

TEST_CASE("compare: a constant offset gives the relMSE, mean difference and z computed by hand") {
    // A = B + 0.1 everywhere, B = 0.5 (relMSE = 0.01 / (0.25 + 0.01)); 2 x 2 pixels, every channel
    // of A with variance 0.0004 (sigma 0.02), B without: the mean over the 12 channels of 4 pixels
    // has standard error sqrt(4 (3 * 0.02)^2) / 12 = 0.01 (channels taken as fully correlated), so
    // z = 0.1 / 0.01 = 10; every channel's z = 0.1 / sqrt(0.0004 + 1e-8).
    const Image a(2, 2, Color(0.6f)), b(2, 2, Color(0.5f)), va(2, 2, Color(0.0004f));
    const ImageComparison c = compareImages(a, b, &va, nullptr);
    const double d = double(0.6f) - double(0.5f);
    CHECK(c.error.relMse == doctest::Approx(d * d / (0.25 + 0.01)).epsilon(1e-12));
    CHECK(c.meanDifference == doctest::Approx(d).epsilon(1e-12));
    CHECK(c.meanDifferenceError == doctest::Approx(std::sqrt(4.0 * 9.0 * double(0.0004f)) / 12.0).epsilon(1e-9));
    CHECK(c.meanZ == doctest::Approx(d / c.meanDifferenceError).epsilon(1e-12));
    CHECK(c.meanZ == doctest::Approx(10.0).epsilon(1e-5));
    REQUIRE(c.largest.size() == 5);
    CHECK(c.largest[0].score == doctest::Approx(d / std::sqrt(double(0.0004f) + 1e-8)).epsilon(1e-6));
    // The threshold of the per-channel test: Sidak over 12 channels at 0.01, two-sided.
    const double level = 1.0 - std::pow(0.99, 1.0 / 12.0);
    CHECK(std::erfc(c.zThreshold / std::sqrt(2.0)) == doctest::Approx(level).epsilon(1e-9));
    CHECK(c.beyondThreshold == 12);
}

TEST_CASE("compare: one pixel brighter and one darker are found where they are, largest first") {
    Image a(8, 4, Color(0.2f)), b(8, 4, Color(0.2f)), var(8, 4, Color(1e-4f));
    a.at(5, 1).g = 0.3f;   // z = 0.1 / sqrt(2e-4) = 7.07
    a.at(2, 3).b = 0.15f;  // z = -3.54
    const ImageComparison c = compareImages(a, b, &var, &var);
    REQUIRE(c.largest.size() >= 2);
    CHECK(c.largest[0].x == 5);
    CHECK(c.largest[0].y == 1);
    CHECK(c.largest[0].channel == 1);
    CHECK(c.largest[0].score > 7.0);
    CHECK(c.largest[1].x == 2);
    CHECK(c.largest[1].y == 3);
    CHECK(c.largest[1].channel == 2);
    CHECK(c.largest[1].score < -3.5);
    CHECK(c.largest[2].score == 0.0);
    // Sidak at 0.01 over 96 channels: |z| > 3.9 fails; 7.07 does, -3.54 does not.
    CHECK(c.beyondThreshold == 1);
    double scale = 0.0;
    const Image d = differenceImage(a, b, &var, &var, 0.0, scale);
    CHECK(scale == 5.0);
    CHECK(d.at(5, 1).r == 1.0f);  // brighter: red, full beyond |z| 5
    CHECK(d.at(5, 1).b == 0.0f);
    CHECK(d.at(2, 3).b > 0.5f);  // darker: blue
    CHECK(d.at(2, 3).r == 0.0f);
    CHECK(isBlack(d.at(0, 0)));
    const Image s = scoreImage(a, b, &var, &var);
    CHECK(s.at(5, 1).g == doctest::Approx(c.largest[0].score).epsilon(1e-6));
    CHECK(s.at(0, 0).r == 0.0f);
}

TEST_CASE("compare: without variances the scores are relative errors and the picture scales to them") {
    Image a(10, 10, Color(1.0f)), b(10, 10, Color(1.0f));
    a.at(3, 4) = Color(2.0f);
    const ImageComparison c = compareImages(a, b, nullptr, nullptr);
    CHECK_FALSE(c.hasVariance);
    CHECK(c.beyondThreshold == 0);
    CHECK(c.largest[0].score == doctest::Approx(1.0 / std::sqrt(1.01)));
    CHECK(c.error.relMse == doctest::Approx(3.0 / 1.01 / 300.0));
    double scale = 0.0;
    const Image d = differenceImage(a, b, nullptr, nullptr, 0.0, scale);
    CHECK(scale == 1.0);  // the 99th percentile of the per-pixel scores is 0: the images equal there
    CHECK(d.at(3, 4).r > 0.0f);
    CHECK(isBlack(d.at(0, 0)));
}

TEST_CASE("compare: NaN pixels are counted and left out; sizes must agree") {
    Image a(2, 1, Color(1.0f)), b(2, 1, Color(1.0f));
    a.at(1, 0).r = std::nanf("");
    const ImageComparison c = compareImages(a, b, nullptr, nullptr);
    CHECK(c.nonFiniteA == 1);
    CHECK(c.error.relMse == 0.0);
    CHECK(c.meanDifference == 0.0);
    const Image small(1, 1);
    CHECK_THROWS_AS(compareImages(a, small, nullptr, nullptr), InputError);
    CHECK_THROWS_AS(compareImages(a, b, &small, nullptr), InputError);
}
