// Tests of the comparison report (report/converge.h): which pixels see a point light
// directly, and that those pixels are left out of every error (lead decision: a path tracer
// cannot sample a path whose both ends are delta positions, so comparing lt/bpt against pt
// there would measure that, not noise).
#include <doctest/doctest.h>
#include <string>
#include "metrics.h"
#include "report/converge.h"
#include "report/label.h"
#include "scene_loader.h"

using namespace ps;

namespace {
std::string pointScene(const std::string& name) {
    return std::string(PATHSPACE_SOURCE_DIR) + "/tests/framework/cli/point-light/" + name + ".scene";
}
}  // namespace

TEST_CASE("report: a point light in view is found in the pixel computed by hand") {
    // in-view.scene: camera at z = -10 looking along +z, fov 40, 16 x 16; light at (1, 1, 0):
    // raster (8 - 8/(10 tan 20), 8 - 8/(10 tan 20)) = (5.80, 5.80) -> pixel (5, 5).
    const Scene scene = loadScene(pointScene("in-view"));
    const std::vector<PointLightPixel> seen = pointLightsInView(scene);
    REQUIRE_MESSAGE(seen.size() == 1, "expected the one point light in view, got " << seen.size());
    CHECK_MESSAGE((seen[0].x == 5 && seen[0].y == 5),
                  "expected pixel (5, 5), got (" << seen[0].x << ", " << seen[0].y << ")");
    CHECK(seen[0].light == 0);
    CHECK(describe(seen[0]) ==
          "pixel (5, 5) sees point light 0 directly: a path tracer cannot sample that path (both ends delta "
          "positions); left out of the error of every algorithm");
    const std::vector<bool> mask = leftOutMask(scene, seen);
    REQUIRE(mask.size() == 256);
    int marked = 0;
    for (bool b : mask) marked += b ? 1 : 0;
    CHECK(marked == 1);
    CHECK(mask[5 * 16 + 5]);
}

TEST_CASE("report: point lights behind an occluder or behind the camera are not in view") {
    const Scene hidden = loadScene(pointScene("hidden"));
    CHECK_MESSAGE(pointLightsInView(hidden).empty(), "an occluded light and one behind the camera were reported");
    const Scene cornell = loadScene(std::string(PATHSPACE_SOURCE_DIR) + "/scenes/cornell-box.scene");
    CHECK_MESSAGE(pointLightsInView(cornell).empty(), "a scene without point lights left pixels out");
    CHECK(leftOutMask(cornell, {}).empty());
}

TEST_CASE("report: a left-out pixel does not count in MSE, relMSE, trimmed relMSE or regions") {
    // Two images equal except in pixel (1, 0), which is 1000 in one and 0 in the other.
    Image img(3, 2, Color(0.5f)), ref(3, 2, Color(0.5f));
    img.at(1, 0) = Color(1000.0f);
    std::vector<bool> mask(6, false);
    mask[1] = true;
    const ErrorMetrics all = computeError(img, ref), without = computeError(img, ref, mask);
    CHECK_MESSAGE(all.mse > 1.0, "the differing pixel must count without a mask: MSE " << all.mse);
    CHECK_MESSAGE(without.mse == 0.0, "MSE with the pixel left out: expected 0, got " << without.mse);
    CHECK(without.relMse == 0.0);
    CHECK(without.relMseTrimmed == 0.0);
    Regions regions;
    regions.names = {"all"};
    regions.ofPixel.assign(6, 0);
    CHECK(regionRelMse(img, ref, regions)[0] > 1.0);
    CHECK(regionRelMse(img, ref, regions, mask)[0] == 0.0);
    // The means are over the remaining pixels: one other pixel off by 0.5 of 5 left.
    img.at(2, 1) = Color(1.0f);
    CHECK(computeError(img, ref, mask).mse == doctest::Approx(0.25 / 5.0).epsilon(1e-12));
}

TEST_CASE("report: labels are drawn with the 5 x 7 font, scaled, clipped and above each image") {
    // "1" at scale 1: the glyph's rows are ..#.., .##.., ..#.. x4, .###. (label.cpp).
    Image img(12, 9);
    drawText(img, 1, 1, "1", 1, Color(1.0f));
    const char* rows[7] = {"..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."};
    int lit = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const bool on = img.at(x, y).r > 0.5f;
            const bool want = x >= 1 && x < 6 && y >= 1 && y < 8 && rows[y - 1][x - 1] == '#';
            CHECK_MESSAGE(on == want, "pixel (" << x << ", " << y << ")");
            lit += on;
        }
    CHECK(lit == 10);
    // Scale 2: every font pixel is 2 x 2; an unknown character is a box; nothing beyond maxX.
    Image big(40, 20);
    drawText(big, 0, 0, "1", 2, Color(1.0f));
    CHECK(big.at(4, 0).r == 1.0f);
    CHECK(big.at(5, 1).r == 1.0f);
    CHECK(big.at(3, 0).r == 0.0f);
    Image box(10, 10);
    drawText(box, 0, 0, "\x01", 1, Color(1.0f));
    CHECK((box.at(0, 0).r == 1.0f && box.at(4, 6).r == 1.0f && box.at(2, 3).r == 0.0f));
    Image clipped(20, 10);
    drawText(clipped, 0, 0, "888", 1, Color(1.0f), 6);
    for (int y = 0; y < 10; ++y)
        for (int x = 6; x < 20; ++x) CHECK(clipped.at(x, y).r == 0.0f);
    CHECK(textWidth("pt 16 spp", 2) == 9 * 6 * 2);
    // The strip, at slide resolution: 60 pixels in all are enlarged 8 times (the most; each pixel an
    // 8 x 8 square) to 480; cells of 240 pixels take the largest font up to a glyph height of 34,
    // scale 4 (28 pixels); a band of (7 + 4) x 4 rows above the images.
    Image a(30, 20, Color(0.25f)), b(30, 20, Color(0.5f));
    a.at(29, 19) = Color(1.0f, 0.0f, 0.0f);
    CHECK(stripFactor(60) == 8);
    CHECK(stripFactor(600) == 2);
    CHECK(stripFactor(768) == 2);
    CHECK(stripFactor(5000) == 1);
    CHECK(stripFactor(10) == 8);
    const Image strip = labelledStrip({a, b}, {"pt", "lt"}, Color(1.0f));
    const int band = 11 * 4;
    REQUIRE(strip.width == 480);
    REQUIRE(strip.height == 160 + band);
    CHECK(strip.at(0, band).r == 0.25f);
    CHECK(strip.at(479, band + 159).r == 0.5f);
    for (int y = band + 152; y < band + 160; ++y)
        for (int x = 232; x < 240; ++x) CHECK(strip.at(x, y).g == 0.0f);  // pixel (29, 19): one square
    CHECK(strip.at(231, band + 159).g == 0.25f);
    int ink = 0;
    for (int y = 0; y < band; ++y)
        for (int x = 0; x < 480; ++x) ink += strip.at(x, y).r == 1.0f;
    CHECK(ink > 0);
    // Long labels wrap at spaces onto a second line, at a smaller font if need be: in 256-pixel
    // cells (128-pixel images, twice) scale 5 at most; "L[DG]S*E|LS*E", 13 characters, fits
    // 256 - 2 x 2 x scale only at scale 3 (234 pixels), so the whole strip is at scale 3.
    std::vector<Image> six(6, Image(128, 128));
    const Image family =
        labelledStrip(six, {"radiosity", "pt LD*E", "drt", "pt LD?[GS]*E", "whitted", "pt L[DG]S*E|LS*E"}, Color(1.0f));
    CHECK(family.width == 1536);
    CHECK(family.height == 256 + 2 * 9 * 3 - 2 * 3 + 4 * 3);  // two lines at scale 3
    CHECK(ink > 0);
    // Seven cells of 256 pixels (lesson 2's plates): "direct-onesample", 16 characters, fits one
    // line only at scale 2; broken after its hyphen, every label fits three lines at scale 4
    // ("direct-" / "onesample 16" does not fit 240 pixels, so "direct-" / "onesample" / "16 spp"):
    // twice the font, so three lines it is.
    std::vector<Image> seven(7, Image(128, 128));
    const Image plates =
        labelledStrip(seven,
                      {"direct-light 16 spp", "direct-bsdf 16 spp", "direct-balance 16 spp", "direct-power 16 spp",
                       "direct-max 16 spp", "direct-onesample 16 spp", "reference"},
                      Color(1.0f));
    CHECK(plates.width == 1792);
    CHECK(plates.height == 256 + 3 * 9 * 4 - 2 * 4 + 4 * 4);
    const auto inkInRow = [&](int cell, int line) {  // ink in that text line of that cell
        int n = 0;
        for (int y = 8 + line * 36; y < 8 + line * 36 + 28; ++y)
            for (int x = cell * 256; x < cell * 256 + 256; ++x) n += plates.at(x, y).r == 1.0f;
        return n;
    };
    CHECK(inkInRow(5, 2) > 0);   // "16 spp" on the third line
    CHECK(inkInRow(6, 1) == 0);  // "reference" on one
}
