// The render parameters lessons register (framework/scene.h, Registry<RenderParameter>): lesson 8's
// ppmradius, ppmphotons, ppmalpha and lesson 11's elements, shots (radiosity) and ambient (whitted).
// A scene file's `render NAME V..` reaches each through the registry and the lesson reads it; a bad
// value is one error naming the file, the line, the parameter and the problem (the count of values,
// a value that is not finite, the range). The command line's `--NAME V,..` is tested in
// tests/framework/cli (render-parameter-*).
#include <doctest/doctest.h>
#include <initializer_list>
#include <string>
#include <vector>
#include "11-classics/radiosity.h"
#include "11-classics/whitted.h"
#include "errors.h"
#include "scene_loader.h"

using namespace ps;

namespace {

const std::string kHead =
    "camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8\n"
    "material w diffuse albedo 0.5 0.5 0.5\n";

std::string errorOf(const std::string& text) {
    try {
        parseScene(text, "test.scene");
    } catch (const InputError& e) { return e.what(); }
    return "(no error)";
}

// `render OPTIONS` on line 3 must fail with a message that starts with "test.scene:3: " and holds
// every one of words.
void expectRenderError(const std::string& options, std::initializer_list<const char*> words) {
    INFO("render " << options);
    const std::string msg = errorOf(kHead + "render " + options + "\n");
    CHECK_MESSAGE(msg.rfind("test.scene:3: ", 0) == 0, msg);
    for (const char* w : words) CHECK_MESSAGE(msg.find(w) != std::string::npos, msg << " (expected: " << w << ")");
}

}  // namespace

TEST_CASE("render parameters: lesson 11's radiosity elements and shots, whitted's ambient, read by the lesson") {
    const Scene defaults = parseScene(kHead, "d.scene");
    const RadiositySettings d = radiositySettings(defaults.settings);
    CHECK(d.nu == 8);
    CHECK(d.nv == 8);
    CHECK(d.shots == 256);
    CHECK(isBlack(whittedAmbient(defaults.settings)));
    const Scene s = parseScene(kHead + "render elements 3 5 shots 7 ambient 0.1 0.2 0.3 algo radiosity\n", "s.scene");
    const RadiositySettings r = radiositySettings(s.settings);
    CHECK(r.nu == 3);
    CHECK(r.nv == 5);
    CHECK(r.shots == 7);
    CHECK(whittedAmbient(s.settings) == Color(0.1f, 0.2f, 0.3f));
    CHECK(s.settings.algo == "radiosity");
    // setRadiositySettings writes what the loader would.
    RenderSettings set;
    setRadiositySettings(set, r);
    CHECK(set.parameters.at("elements") == s.settings.parameters.at("elements"));
    CHECK(set.parameters.at("shots") == s.settings.parameters.at("shots"));
}

TEST_CASE("render parameters: a bad value of lesson 11's is one error naming the line, the parameter and the problem") {
    // The count of values.
    expectRenderError("elements 4", {"option 'elements' needs 2 value(s), got 1"});
    expectRenderError("elements 4 shots 9", {"option 'elements' needs 2 value(s), got 1 before 'shots'"});
    expectRenderError("ambient 0.1 0.1", {"option 'ambient' needs 3 value(s), got 2"});
    expectRenderError("shots", {"option 'shots' needs 1 value(s), got 0"});
    // Not a finite number.
    expectRenderError("elements 4 nan", {"'nan' for 'elements' is not a finite number"});
    expectRenderError("ambient 0 inf 0", {"'inf' for 'ambient' is not a finite number"});
    expectRenderError("shots 1e40", {"'1e40' for 'shots' is out of range"});
    expectRenderError("shots many", {"malformed number 'many' for 'shots'"});
    // The range.
    expectRenderError("elements 0 4", {"'elements' must be whole numbers from 1 to 256", "got 0 4"});
    expectRenderError("elements 4 257", {"'elements' must be whole numbers from 1 to 256", "got 4 257"});
    expectRenderError("elements 4 2.5", {"'elements' must be whole numbers", "got 4 2.5"});
    expectRenderError("shots 0", {"'shots' must be a whole number of steps from 1 to 1e9", "got 0"});
    expectRenderError("shots 1.5", {"'shots' must be a whole number", "got 1.5"});
    expectRenderError("ambient 0.1 -0.1 0", {"'ambient' must not be negative", "got 0.1 -0.1 0"});
    expectRenderError("ambient 1e31 0 0", {"'ambient' must not be negative nor above 1e30", "got 1e31 0 0"});
}

TEST_CASE(
    "render parameters: a bad value of lesson 8's ppm is one error naming the line, the parameter and the problem") {
    expectRenderError("ppmradius 0", {"'ppmradius' must be a positive number", "got 0"});
    expectRenderError("ppmradius nan", {"'nan' for 'ppmradius' is not a finite number"});
    expectRenderError("ppmphotons 2.5", {"'ppmphotons' must be a whole number of photon paths", "got 2.5"});
    expectRenderError("ppmalpha 1", {"'ppmalpha' must lie between 0 and 1", "got 1"});
    expectRenderError("ppmalpha 0.5 0.6", {"unknown option '0.6' for 'render'"});
}
