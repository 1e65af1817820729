// Bad scene input: every kind of mistake in a scene file or an OBJ mesh must throw
// ps::InputError whose one-line message names the file, the line ("test.scene:3:") and the
// problem in words a student understands. One TEST_CASE per kind of bad input.
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>
#include "camera.h"
#include "errors.h"
#include "scene_loader.h"

using namespace ps;

namespace {
// Render parameters as lessons register them (lesson 8's ppm radius schedule, lesson 11's radiosity
// elements, for instance): one number, and two.
[[maybe_unused]] const bool testParameter = Registry<RenderParameter>::add(
    "testfraction", {"a fraction for the loader's tests", "F", 1, [](const std::vector<float>& v) {
                         return v[0] > 0.0f && v[0] < 1.0f ? std::string() : std::string("must lie between 0 and 1");
                     }});
[[maybe_unused]] const bool testPair = Registry<RenderParameter>::add(
    "testpair", {"two counts for the loader's tests", "N M", 2, [](const std::vector<float>& v) {
                     return v[0] >= 1.0f && v[1] >= 1.0f ? std::string() : std::string("must be at least 1 each");
                 }});
[[maybe_unused]] const bool testAny = Registry<RenderParameter>::add("testany", {"any finite number", "X", 1, nullptr});
}  // namespace

namespace {

// Lines 1 and 2 of most test scenes; the line under test is line 3.
const std::string kHead =
    "camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8\n"
    "material w diffuse albedo 0.5 0.5 0.5\n";

// The message of the InputError that parsing `text` throws; fails the test if it throws
// something else or nothing.
std::string errorOf(const std::string& text, const std::string& path = "test.scene") {
    try {
        parseScene(text, path);
    } catch (const InputError& e) { return e.what(); } catch (const std::exception& e) {
        FAIL("expected ps::InputError, got another exception: " << e.what());
    }
    FAIL("expected ps::InputError, but the scene loaded:\n" << text);
    return "";
}

// The message contains every one of `words` and is one line.
void checkMessage(const std::string& msg, std::initializer_list<const char*> words) {
    INFO("message: " << msg);
    for (const char* w : words) CHECK_MESSAGE(msg.find(w) != std::string::npos, "missing '" << w << "'");
    CHECK_MESSAGE(msg.find('\n') == std::string::npos, "the message must be one line");
}

// Parsing kHead + line fails on line 3 with a message containing `words`.
void expectLine3(const std::string& line, std::initializer_list<const char*> words) {
    INFO("scene line 3: " << line);
    const std::string msg = errorOf(kHead + line + "\n");
    CHECK_MESSAGE(msg.rfind("test.scene:3: ", 0) == 0, "message must start with 'test.scene:3: ': " << msg);
    checkMessage(msg, words);
}

// A folder under the build tree for the files these tests write.
std::string scratchDir() {
    const std::string dir = std::string(PATHSPACE_BINARY_DIR) + "/test-scene-errors";
    std::filesystem::create_directories(dir);
    return dir;
}

std::string writeFile(const std::string& name, const std::string& text) {
    const std::string path = scratchDir() + "/" + name;
    std::ofstream(path) << text;
    return path;
}

// Parses kHead + "mesh NAME.obj OPTIONS" as a scene file in the scratch folder, with NAME.obj
// containing objText, and returns the error message.
std::string meshError(const std::string& name, const std::string& objText, const std::string& options = "material w") {
    writeFile(name + ".obj", objText);
    return errorOf(kHead + "mesh " + name + ".obj " + options + "\n", scratchDir() + "/test.scene");
}

}  // namespace

TEST_CASE("scene errors: the test scenes are fine without the bad line (control)") {
    // The same head with good versions of the lines below loads: the errors come from the bad lines.
    CHECK_NOTHROW(parseScene(kHead + "sphere center 0 0 0 radius 1 material w\n", "test.scene"));
    CHECK_NOTHROW(parseScene(kHead + "quad 0 0 0  1 0 0  1 1 0  0 1 0 emission 1 1 1\n", "test.scene"));
    writeFile("good.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 3\nf -4 -3 -2\n");
    CHECK_NOTHROW(
        parseScene(kHead + "mesh good.obj material w scale 2 translate 1 2 3\n", scratchDir() + "/test.scene"));
}

TEST_CASE("scene errors: unknown keyword") {
    expectLine3("spere center 0 0 0 radius 1 material w", {"unknown keyword 'spere'", "sphere"});
}

TEST_CASE("scene errors: unknown option") {
    expectLine3("sphere center 0 0 0 radius 1 material w colour 1 0 0",
                {"unknown option 'colour'", "'sphere'", "center, emission, material, radius"});
    expectLine3("material m diffuse albedo 0.5 0.5 0.5 exponent 10", {"unknown option 'exponent'"});
}

TEST_CASE("scene errors: missing scene file") {
    const std::string path = scratchDir() + "/no-such-file.scene";
    try {
        loadScene(path);
        FAIL("loadScene of a missing file must throw");
    } catch (const InputError& e) { checkMessage(e.what(), {"no-such-file.scene: ", "cannot open scene file"}); }
}

TEST_CASE("scene errors: missing mesh file") {
    const std::string msg = errorOf(kHead + "mesh nope.obj material w\n", scratchDir() + "/test.scene");
    checkMessage(msg, {"test.scene:3: ", "cannot open mesh file", "nope.obj"});
}

TEST_CASE("scene errors: malformed number") {
    for (const char* bad : {"1.2.3", "abc", "1e", "1,5", "0x10", "--1", "1f"}) {
        CAPTURE(bad);
        expectLine3(std::string("sphere center 0 0 0 radius ") + bad + " material w",
                    {"malformed number", bad, "'radius'"});
        expectLine3(std::string("sphere center 0 ") + bad + " 0 radius 1 material w",
                    {"malformed number", bad, "'center'"});
        expectLine3(std::string("triangle 0 0 0  1 0 0  0 ") + bad + " 0 material w",
                    {"malformed number", bad, "corner 3"});
    }
    expectLine3("sphere center 0 0 0 radius 1e39 material w", {"1e39", "out of range"});
    expectLine3("render spp 1.5", {"malformed integer '1.5'", "'spp'"});
}

TEST_CASE("scene errors: negative radius") {
    expectLine3("sphere center 0 0 0 radius -1 material w", {"negative radius -1", "positive"});
    expectLine3("sphere center 0 0 0 radius 0 material w", {"'radius' must be positive"});
    expectLine3("sphere center 0 0 0 radius -0 material w", {"'radius' must be positive"});
}

TEST_CASE("scene errors: NaN and Inf values") {
    for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity"}) {
        CAPTURE(bad);
        expectLine3(std::string("sphere center 0 0 0 radius ") + bad + " material w", {bad, "not a finite number"});
        expectLine3(std::string("quad 0 0 0  1 0 0  1 ") + bad + " 0  0 1 0 material w", {bad, "not a finite number"});
        expectLine3(std::string("pointlight position 0 0 0 intensity 1 ") + bad + " 1", {bad, "not a finite number"});
    }
    const std::string msg = meshError("nanvertex", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n");
    checkMessage(msg, {"nanvertex.obj:2: ", "'nan'", "vertex coordinate", "test.scene:3"});
}

TEST_CASE("scene errors: empty mesh (vertices but no faces)") {
    const std::string msg = meshError("empty", "# three vertices, no face\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    checkMessage(msg, {"empty.obj: ", "empty mesh", "no faces", "test.scene:3"});
}

TEST_CASE("scene errors: degenerate triangle") {
    SUBCASE("in a 'triangle' line") {
        expectLine3("triangle 0 0 0  1 0 0  2 0 0 material w", {"degenerate triangle", "zero area"});
        expectLine3("triangle 0 0 0  0 0 0  0 1 0 material w", {"degenerate triangle", "zero area"});
    }
    SUBCASE("in a 'quad' line") {
        expectLine3("quad 0 0 0  1 0 0  2 0 0  0 1 0 material w", {"degenerate quad", "corners 1, 2, 3", "zero area"});
        expectLine3("quad 0 0 0  1 0 0  1 1 0  1 1 0 material w", {"degenerate quad", "corners 1, 3, 4", "zero area"});
    }
    SUBCASE("a quad whose corners are not in order (a bow tie), or concave at corner 2 or 4") {
        expectLine3("quad 0 0 0  1 0 0  0 1 0  1 1 0 emission 1 1 1", {"face opposite ways", "not in order"});
        expectLine3("quad 1 0 0  0.2 0.2 0  0 1 0  0 0 0 material w",
                    {"face opposite ways", "concave at corner 2 or 4"});
        // Concave at corner 1 or 3 is fine: the split diagonal 1-3 lies inside.
        CHECK_NOTHROW(parseScene(kHead + "quad 0 0 0  1 0 0  0.2 0.2 0  0 1 0 material w\n", "test.scene"));
        CHECK_NOTHROW(parseScene(kHead + "quad 0.2 0.2 0  0 1 0  0 0 0  1 0 0 material w\n", "test.scene"));
    }
    SUBCASE("inside an OBJ: the message names the OBJ file and the face's line") {
        const std::string msg = meshError("degenerate",
                                          "# a good face, then a degenerate one\n"
                                          "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\n"
                                          "f 1 2 4\n"
                                          "\n"
                                          "f 1 2 3\n");
        checkMessage(msg, {"degenerate.obj:8: ", "degenerate face", "zero area", "test.scene:3"});
    }
    SUBCASE("a face with two vertices inside an OBJ") {
        const std::string msg = meshError("twovertices", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\nf 1 2 3\n");
        checkMessage(msg, {"twovertices.obj:4: ", "face with 2 vertices", "test.scene:3"});
    }
}

TEST_CASE("scene errors: OBJ vertex index out of range") {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    checkMessage(meshError("range", obj + "f 1 2 7\n"),
                 {"range.obj:5: ", "vertex index 7 out of range", "3 vertices", "test.scene:3"});
    checkMessage(meshError("relative", obj + "f -1 -2 -5\n"),
                 {"relative.obj:5: ", "relative vertex index", "before the first vertex", "test.scene:3"});
    checkMessage(meshError("zero", obj + "f 1 2 0\n"), {"zero.obj:5: ", "malformed vertex index '0'", "test.scene:3"});
    checkMessage(meshError("letter", obj + "f 1 2 a\n"),
                 {"letter.obj:5: ", "malformed vertex index 'a'", "test.scene:3"});
}

TEST_CASE("scene errors: unknown material") {
    expectLine3("sphere center 0 0 0 radius 1 material wall", {"unknown material 'wall'", "defined so far: w"});
    // Materials must be defined before they are used.
    const std::string msg = errorOf(kHead +
                                    "sphere center 0 0 0 radius 1 material late\n"
                                    "material late diffuse albedo 0.5 0.5 0.5\n");
    checkMessage(msg, {"test.scene:3: ", "unknown material 'late'"});
    // A mesh without 'material' needs an MTL.
    checkMessage(meshError("nomtl", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ""),
                 {"nomtl.obj:4: ", "face has no material", "test.scene:3"});
    expectLine3("material m plastic albedo 0.5 0.5 0.5", {"unknown material type 'plastic'", "diffuse, phong"});
}

TEST_CASE("scene errors: duplicate material") {
    expectLine3("material w phong albedo 0.5 0.5 0.5 exponent 10",
                {"material 'w' is defined twice", "first on line 2"});
    // The loader's own name for black emitters cannot be taken (it would give emitters an albedo).
    expectLine3("material (emitter) diffuse albedo 1 1 1", {"'(emitter)'", "the loader's own"});
}

TEST_CASE("scene errors: missing camera") {
    const std::string msg = errorOf("material w diffuse albedo 0.5 0.5 0.5\nsphere center 0 0 0 radius 1 material w\n");
    CHECK_MESSAGE(msg.rfind("test.scene: ", 0) == 0, msg);
    checkMessage(msg, {"no 'camera'", "needs a camera"});
    checkMessage(errorOf(""), {"test.scene: ", "no 'camera'"});
    // A second camera is an error too.
    expectLine3("camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8", {"second 'camera'"});
}

TEST_CASE("scene errors: bad resolution or field of view") {
    // The camera on line 3, after a comment and an empty line (they count as lines).
    auto camera = [](const std::string& options, std::initializer_list<const char*> words) {
        const std::string text = "# a comment line\n\ncamera eye 0 0 -5  target 0 0 0  " + options + "\n";
        INFO("camera options: " << options);
        const std::string msg = errorOf(text);
        CHECK_MESSAGE(msg.rfind("test.scene:3: ", 0) == 0, msg);
        checkMessage(msg, words);
    };
    camera("fov 0 resolution 8 8", {"'fov' must be between 0 and 180", "got 0"});
    camera("fov 180 resolution 8 8", {"'fov' must be between 0 and 180", "got 180"});
    camera("fov -30 resolution 8 8", {"'fov'", "got -30"});
    camera("fov 40 resolution 0 8", {"'resolution' must be between 1 and 16384", "got 0 8"});
    camera("fov 40 resolution 8 -1", {"'resolution'", "got 8 -1"});
    camera("fov 40 resolution 20000 8", {"'resolution'", "16384"});
    // Each side within 16384, but more pixels than a render may have (the memory model, issue 31:
    // 16384 x 16384 needed more than 8 GB).
    camera("fov 40 resolution 16384 16384", {"'resolution' 16384 16384 is 268435456 pixels", "4194304", "4 GiB"});
    camera("fov 40 resolution 2049 2048", {"is 4196352 pixels, more than the 4194304"});
    CHECK_NOTHROW(parseScene("camera eye 0 0 -5  target 0 0 0  fov 40 resolution 4096 1024\n", "ok.scene"));
    camera("fov 40 resolution 8.5 8", {"malformed integer '8.5'", "'resolution' (width)"});
    camera("fov 40 resolution 8", {"option 'resolution' needs 2 value(s)"});
    camera("fov 40 resolution 8 8 up 0 0 1", {"'up' is parallel to the view direction"});
    camera("fov 40 resolution 8 8 target 0 0 -5", {"option 'target' given twice"});
}

namespace {
// A camera model of this test's own (the framework knows none; lessons register theirs): a
// keyword `testmodel R` with one value, and `testextra` with two, which only makes sense with it.
struct TestModel : CameraModel {
    float r = 0.0f;
    Vec3 samplePoint(const Vec2&) const override { return Vec3(0.0f); }
    float pdfPoint() const override { return 1.0f; }
    Ray ray(const Vec2&, const Vec3& z) const override { return Ray(z, Vec3(0, 0, 1)); }
    bool rasterOfDirection(const Vec3&, const Vec3&, Vec2&) const override { return false; }
    float We(const Vec3&, const Vec3&) const override { return 0.0f; }
    float pdfDirection(const Vec3&, const Vec3&) const override { return 0.0f; }
    bool hit(const Ray&, float&, Vec3&) const override { return false; }
    std::string describe() const override { return "testmodel " + std::to_string(r); }
};
std::shared_ptr<const CameraModel> makeTestModel(const Camera&, const CameraModelArgs& args) {
    if (args.has("testextra") && !args.has("testmodel")) args.fail("'testextra' without 'testmodel'");
    const float r = args.number("testmodel", 0.0f);
    if (r < 0.0f) args.fail("'testmodel' must not be negative, got " + args.text("testmodel"));
    if (r == 0.0f) return nullptr;
    auto m = std::make_shared<TestModel>();
    m->r = r;
    return m;
}
[[maybe_unused]] const bool registered =
    Registry<CameraModelType>::add("testmodel", CameraModelType{{{"testmodel", 1}, {"testextra", 2}}, makeTestModel});
}  // namespace

TEST_CASE("scene errors: a camera model's keywords reach its maker, its errors name the line") {
    auto camera = [](const std::string& options, std::initializer_list<const char*> words) {
        const std::string text =
            "# a comment line\n\ncamera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8  " + options + "\n";
        INFO("camera options: " << options);
        const std::string msg = errorOf(text);
        CHECK_MESSAGE(msg.rfind("test.scene:3: ", 0) == 0, msg);
        checkMessage(msg, words);
    };
    camera("testmodel -0.1", {"'testmodel' must not be negative", "got -0.1"});
    camera("testmodel nan", {"'nan'", "'testmodel'", "not a finite number"});
    camera("testextra 1 2", {"'testextra' without 'testmodel'"});
    camera("testmodel 0.1 0.2", {"'0.2'"});
    camera("testextra 1", {"option 'testextra' needs 2 value(s)"});
    camera("nomodel 1", {"unknown option 'nomodel'", "testmodel"});
    // Accepted: 0 (the maker's pinhole), a model otherwise.
    const Scene pin = parseScene("camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8  testmodel 0\n", "t.scene");
    CHECK(pin.camera.isPinhole());
    const Scene model =
        parseScene("camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8  testmodel 0.5\n", "t.scene");
    REQUIRE(!model.camera.isPinhole());
    CHECK(dynamic_cast<const TestModel*>(model.camera.model())->r == 0.5f);
    CHECK(model.caps.describe().find("camera=testmodel") != std::string::npos);
}

TEST_CASE("scene errors: missing required option") {
    expectLine3("sphere center 0 0 0 material w", {"'sphere' needs the option 'radius'"});
    expectLine3("sphere radius 1 material w", {"'sphere' needs the option 'center'"});
    expectLine3("sphere center 0 0 0 radius 1", {"'sphere' needs the option 'material'"});
    expectLine3("quad 0 0 0  1 0 0  1 1 0  0 1 0", {"'quad' needs the option 'material'"});
    expectLine3("material m diffuse", {"'material' needs the option 'albedo'"});
    expectLine3("material m phong albedo 0.5 0.5 0.5", {"'material' needs the option 'exponent'"});
    expectLine3("material m dielectric", {"'material' needs the option 'ior'"});
    expectLine3("material m", {"'material' needs a type"});
    expectLine3("pointlight position 0 0 0", {"'pointlight' needs the option 'intensity'"});
    expectLine3("background", {"'background' needs the option 'radiance'"});
    expectLine3("mesh", {"'mesh' needs a file name"});
    // Too few values: the next option's name comes, or the line ends.
    expectLine3("sphere center 0 0 radius 1 material w", {"option 'center' needs 3 value(s), got 2 before 'radius'"});
    expectLine3("sphere center 0 0 0 material w radius", {"option 'radius' needs 1 value(s), got 0"});
    expectLine3("triangle 0 0 0  1 0 0  0 1 material w", {"malformed number 'material'", "corner 3"});
    const std::string msg = errorOf("camera eye 0 0 -5  fov 40  resolution 8 8\n");
    checkMessage(msg, {"test.scene:1: ", "'camera' needs the option 'target'"});
}

TEST_CASE("scene errors: option given twice") {
    expectLine3("sphere center 0 0 0 radius 1 radius 2 material w", {"option 'radius' given twice"});
    expectLine3("quad 0 0 0  1 0 0  1 1 0  0 1 0 material w material w", {"option 'material' given twice"});
}

TEST_CASE("scene errors: a second background") {
    const std::string msg = errorOf(kHead + "background radiance 1 1 1\nbackground radiance 2 2 2\n");
    checkMessage(msg, {"test.scene:4: ", "second 'background'"});
}

TEST_CASE("scene errors: albedo above 1") {
    expectLine3("material m diffuse albedo 0.5 1.01 0.5", {"'albedo' must be at most 1"});
    expectLine3("material m phong albedo 2 2 2 exponent 10", {"'albedo' must be at most 1"});
    expectLine3("material m mirror albedo 1 1 1.5", {"'albedo' must be at most 1"});
    expectLine3("material m diffuse albedo -0.1 0.5 0.5", {"'albedo' must not be negative"});
}

TEST_CASE("scene errors: negative emission") {
    expectLine3("quad 0 0 0  1 0 0  1 1 0  0 1 0 emission -1 1 1", {"'emission' must not be negative"});
    expectLine3("sphere center 0 0 0 radius 1 emission 1 1 -0.5", {"'emission' must not be negative"});
    expectLine3("pointlight position 0 0 0 intensity -1 -1 -1", {"'intensity' must not be negative"});
    expectLine3("background radiance 0 -1 0", {"'radiance' must not be negative"});
}

TEST_CASE("scene errors: other values out of their range") {
    expectLine3("material m phong albedo 0.5 0.5 0.5 exponent -1", {"'exponent' must not be negative"});
    expectLine3("material m dielectric ior 0", {"'ior' must be positive"});
    expectLine3("mesh x.obj material w scale 0", {"'scale' must be positive"});
    expectLine3("render spp 0", {"'spp' must be at least 1"});
    expectLine3("render maxdepth -1", {"'maxdepth' must not be negative"});
    // A render parameter some lesson registers (this test registers its own: testfraction, testpair,
    // testany): the loader checks the count of its values, that each is a finite number, and its
    // range, and refuses a name no lesson registered.
    expectLine3("render testfraction 1", {"'testfraction' must lie between 0 and 1", "got 1"});
    expectLine3("render testfraction", {"'testfraction' needs 1 value(s)"});
    expectLine3("render testfraction nan", {"'nan' for 'testfraction' is not a finite number"});
    expectLine3("render testfractoin 0.5", {"unknown option 'testfractoin' for 'render'", "testfraction"});
    expectLine3("render testpair 0 4", {"'testpair' must be at least 1 each", "got 0 4"});
    expectLine3("render testpair 4", {"'testpair' needs 2 value(s), got 1"});
    expectLine3("render testpair 4 spp 2", {"'testpair' needs 2 value(s), got 1 before 'spp'"});
    expectLine3("render testpair 4 inf", {"'inf' for 'testpair' is not a finite number"});
    expectLine3("render testpair 4 1e39", {"'1e39' for 'testpair' is out of range"});
    expectLine3("render testpair 4 four", {"malformed number 'four' for 'testpair'"});
    expectLine3("render testany -1e30 spp 0", {"'spp' must be at least 1"});
}

TEST_CASE("scene errors: a render parameter's values checked in one place (renderParameterProblem)") {
    // What the loader and the command line both ask: the count, finite values, then the lesson's check.
    const RenderParameter& pair = *Registry<RenderParameter>::find("testpair");
    CHECK(renderParameterProblem(pair, {1.0f, 2.0f}).empty());
    CHECK(renderParameterProblem(pair, {1.0f}) == "needs 2 numbers (N M), got 1");
    CHECK(renderParameterProblem(pair, {1.0f, 2.0f, 3.0f}) == "needs 2 numbers (N M), got 3");
    CHECK(renderParameterProblem(pair, {1.0f, std::nanf("")}) == "needs finite numbers");
    CHECK(renderParameterProblem(pair, {1.0f, INFINITY}) == "needs finite numbers");
    CHECK(renderParameterProblem(pair, {0.5f, 2.0f}) == "must be at least 1 each");
    const RenderParameter& any = *Registry<RenderParameter>::find("testany");
    CHECK(renderParameterProblem(any, {-1e30f}).empty());  // no check: any finite number
    CHECK(renderParameterProblem(any, {}) == "needs 1 number (X), got 0");
}

TEST_CASE("scene errors: a quad is kept as written (Scene::quads), its two triangles after it") {
    const Scene s = parseScene(
        "camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8\n"
        "material w diffuse albedo 0.5 0.5 0.5\n"
        "triangle 0 0 0  1 0 0  0 1 0  material w\n"
        "quad 0 0 1  2 0 1  2 1 1  0 1 1  material w\n"
        "render testpair 3 5 testfraction 0.75\n",
        "quads.scene");
    REQUIRE(s.quads.size() == 1);
    CHECK(s.quads[0].line == 4);
    CHECK(s.quads[0].prim == 1);
    CHECK(s.quads[0].corners[1] == Vec3(2, 0, 1));
    CHECK(s.quads[0].corners[3] == Vec3(0, 1, 1));
    CHECK(s.triangles[s.prims[1].index].p2 == Vec3(2, 1, 1));
    CHECK(s.triangles[s.prims[2].index].p1 == Vec3(2, 1, 1));
    CHECK(renderParameterValues(s.settings, "testpair", {}) == std::vector<float>{3.0f, 5.0f});
    CHECK(renderParameter(s.settings, "testfraction", 0.0f) == 0.75f);
    CHECK(renderParameter(s.settings, "testany", -2.0f) == -2.0f);  // not set: the fallback
    CHECK(renderParameter(s.settings, "spp", -1.0f) == -1.0f);      // not a render parameter
}

TEST_CASE("scene errors: values too large for float light transport") {
    expectLine3("quad 0 0 0  1 0 0  1 1 0  0 1 0 emission 1e31 1 1", {"'emission' above 1e30"});
    expectLine3("pointlight position 0 0 0 intensity 3e38 3e38 3e38", {"'intensity' above 1e30"});
    expectLine3("background radiance 1e35 0 0", {"'radiance' above 1e30"});
    expectLine3("material m phong albedo 0.5 0.5 0.5 exponent 5e8", {"'exponent' above 1e7", "mirror"});
    // Below the cap, but radiance x area x pi overflows: the light's own line is named.
    expectLine3("quad -1e5 0 -1e5  1e5 0 -1e5  1e5 0 1e5  -1e5 0 1e5 emission 1e30 1e30 1e30",
                {"power", "overflows float"});
}

TEST_CASE("scene errors: a byte order mark is accepted, a NUL byte is reported") {
    // Some editors start a UTF-8 file with the bytes EF BB BF: not part of the keyword.
    CHECK_NOTHROW(parseScene("\xEF\xBB\xBF" + kHead, "bom.scene"));
    const std::string msg = errorOf(kHead + std::string("quad 0 0 0\0 1 0 0", 17) + "\n");
    CHECK_MESSAGE(msg.rfind("test.scene:3: ", 0) == 0, msg);
    checkMessage(msg, {"NUL byte"});
    CHECK_MESSAGE(msg.find('\0') == std::string::npos, "the message must not carry the NUL byte itself");
}

TEST_CASE("scene errors: huge and far-away scenes are not called degenerate") {
    // Float squares of lengths overflow near 1e19; the checks run in double.
    for (const char* size : {"1e15", "1e18", "1e30"}) {
        CAPTURE(size);
        const std::string s = size;
        CHECK_NOTHROW(parseScene(kHead + "quad -" + s + " 0 -" + s + "  " + s + " 0 -" + s + "  " + s + " 0 " + s +
                                     "  -" + s + " 0 " + s + " material w\n",
                                 "huge.scene"));
    }
}

TEST_CASE("scene errors: OBJ faces with more than 255 corners, MTL values, files that are not files") {
    // tinyobjloader keeps a face's corner count in a byte: a 300-gon would silently lose corners.
    std::string obj;
    for (int i = 0; i < 300; ++i) {
        const double a = 2.0 * 3.141592653589793 * i / 300.0;
        obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    obj += "f";
    for (int i = 1; i <= 300; ++i) obj += " " + std::to_string(i);
    checkMessage(meshError("polygon300", obj + "\n"), {"polygon300.obj:301: ", "300 corners", "at most 255"});

    const std::string tri = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
    struct Bad {
        const char* mtl;
        const char* words;
    };
    for (const Bad& b : {Bad{"newmtl a\nKd nan 0 0\n", "'nan'"}, Bad{"newmtl a\nKd abc 0.5 0.5\n", "'abc'"},
                         Bad{"newmtl a\nKd 0.5 0.5\n", "three numbers"}, Bad{"newmtl a\nKd 1.5 0 0\n", "at most 1"},
                         Bad{"newmtl a\nKe 1e39 1 1\n", "'1e39'"}, Bad{"newmtl a\nKe 1e31 1 1\n", "above 1e30"},
                         Bad{"newmtl a\nKe -1 2 2\n", "must not be negative"}}) {
        CAPTURE(b.mtl);
        writeFile("m.mtl", b.mtl);
        checkMessage(meshError("withmtl", tri, ""), {"m.mtl:2: ", b.words, "withmtl.obj"});
    }

    // A device never ends and a folder is no file: refused before reading.
    const std::string zero = errorOf(kHead + "mesh /dev/zero material w\n");
    checkMessage(zero, {"test.scene:3: ", "/dev/zero", "not a regular file"});
    std::filesystem::create_directories(scratchDir() + "/folder.obj");
    checkMessage(errorOf(kHead + "mesh folder.obj material w\n", scratchDir() + "/test.scene"), {"not a regular file"});
}

TEST_CASE("scene errors: features below float resolution (a tiny sphere far out, a scene moved by 1e7)") {
    // A sphere whose radius is a few float steps of its centre's coordinates: rejected.
    expectLine3("sphere center 1 1 1 radius 1e-8 emission 1e16 1e16 1e16", {"16 float steps", "radius 1e-8"});
    expectLine3("sphere center 1e6 0 0 radius 0.5 material w", {"float cannot resolve"});
    CHECK_NOTHROW(parseScene(kHead + "sphere center 1 1 1 radius 1e-5 emission 1 1 1\n", "ok.scene"));
    // The Cornell box moved by 1e7: the light 0.1 below the ceiling lands on it. Not refused
    // (the image is still finite), but the scene says so.
    const std::string box = "quad 0 0 0  556 0 0  556 548.8 0  0 548.8 0 material w\n";
    const Scene near = parseScene(kHead + box, "near.scene");
    CHECK_MESSAGE(near.warnings.empty(), "a box at the origin needs no warning");
    std::string far = kHead + "quad 1e7 0 0  10000556 0 0  10000556 548.8 0  1e7 548.8 0 material w\n";
    const Scene moved = parseScene(far, "moved.scene");
    REQUIRE_MESSAGE(moved.warnings.size() == 1, "expected one warning for coordinates near 1e7");
    CHECK_MESSAGE(moved.warnings[0].find("resolved by float only to 1") != std::string::npos, moved.warnings[0]);
}
