// Tests of the comparison report (app/report/converge.h): which pixels see a point light
// directly, and that those pixels are left out of every error (lead decision: a path tracer
// cannot sample a path whose both ends are delta positions, so comparing lt/bpt against pt
// there would measure that, not noise).
#include <doctest/doctest.h>
#include <string>
#include "metrics.h"
#include "report/converge.h"
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
