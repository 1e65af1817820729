// Lesson 11's thin lens as a camera model of the scene file (lessons/11-classics/lens_camera.cpp):
// the keywords `lens R focus F` on a camera line reach it through the framework's camera model
// registry; a bad value is one error naming the file, the line and the problem.
#include <doctest/doctest.h>
#include <initializer_list>
#include <string>
#include "11-classics/thinlens.h"
#include "errors.h"
#include "scene_loader.h"

using namespace ps;

namespace {

std::string errorOf(const std::string& text) {
    try {
        parseScene(text, "test.scene");
    } catch (const InputError& e) { return e.what(); }
    return "(no error)";
}

}  // namespace

TEST_CASE("thin lens scene: a bad lens (lens RADIUS focus DISTANCE) is one error naming the line") {
    auto camera = [](const std::string& options, std::initializer_list<const char*> words) {
        const std::string text =
            "# a comment line\n\ncamera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8  " + options + "\n";
        INFO("camera options: " << options);
        const std::string msg = errorOf(text);
        CHECK_MESSAGE(msg.rfind("test.scene:3: ", 0) == 0, msg);
        for (const char* w : words) CHECK_MESSAGE(msg.find(w) != std::string::npos, msg << " (expected: " << w << ")");
    };
    camera("lens -0.1", {"'lens' (the lens radius) must not be negative", "got -0.1"});
    camera("lens nan", {"'nan'", "'lens'", "not a finite number"});
    camera("lens inf", {"'lens'"});
    camera("lens 1e-30", {"'lens' radius 1e-30", "float's normal range"});
    camera("lens 1e25", {"'lens' radius 1e25", "float's normal range"});
    camera("lens 0.1 focus 0", {"'focus'", "must be positive"});
    camera("lens 0.1 focus -2", {"'focus'", "must be positive"});
    camera("lens 0.1 focus nan", {"'nan'", "'focus'", "not a finite number"});
    camera("focus 2", {"'focus' without 'lens RADIUS'"});
    camera("lens 0.1 0.2", {"'0.2'"});
    // Issue 31: 'lens 2e-19' passed the normal-range test (pi r^2 = 1.3e-37) and light tracing gave
    // NaN. Refused as a sphere that small is: below 16 float steps of the eye's coordinates (here
    // 5: a step of 4.8e-7) ...
    camera("lens 2e-19", {"'lens' radius 2e-19 is below 16 float steps", "eye's coordinates"});
    camera("lens 7e-6", {"'lens' radius 7e-6 is below 16 float steps"});
    // ... and, at the origin, where float steps are tiny, by the pixel's importance through it.
    const auto atOrigin = [](const std::string& radius) {
        return "camera eye 0 0 0  target 0 0 1  fov 40  resolution 8 8  lens " + radius + "\n";
    };
    for (const char* r : {"2e-19", "1e-9"}) {
        const std::string msg = errorOf(atOrigin(r));
        CHECK_MESSAGE(msg.find("'lens' radius " + std::string(r) + ": a pixel's importance") != std::string::npos, msg);
        CHECK_MESSAGE(msg.find("beyond 2^64") != std::string::npos, msg);
    }
    CHECK_NOTHROW(parseScene(atOrigin("1e-8"), "t.scene"));
    CHECK_NOTHROW(parseScene("camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8  lens 8e-6\n", "t.scene"));
    // Accepted: radius 0 (the pinhole), focus defaulting to the target's distance.
    const Scene pin = parseScene("camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8  lens 0\n", "t.scene");
    CHECK(pin.camera.isPinhole());
    const Scene lens = parseScene("camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8  lens 0.5\n", "t.scene");
    REQUIRE(thinLens(lens.camera) != nullptr);
    CHECK(thinLens(lens.camera)->radius() == 0.5f);
    CHECK(thinLens(lens.camera)->focus() == 5.0f);
    CHECK(lens.caps.describe().find("camera=lens") != std::string::npos);
}
