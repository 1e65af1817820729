// Lesson 11, graded: Heckbert's classification of a path's vertices (heckbert.h, Eq. 11.1), on
// paths made by hand in a scene with one material of every kind: exact, no statistics.
#include "paths_support.h"

using namespace lesson11paths;
using ps::VertexType;

namespace {

std::string letter(VertexType t) { return std::string(1, ps::typeLetter(t)); }

// "LDSE"-style string of the path, from the student's vertexType, vertex by vertex.
std::string byVertex(const ps::Scene& scene, const ps::Path& x) {
    std::string s;
    for (size_t i = 0; i < x.size(); ++i) {
        const VertexType t = ps::vertexType(scene, x, i);
        s += int(t) < ps::kVertexTypes ? ps::typeLetter(t) : '?';
    }
    return s;
}

}  // namespace

TEST_CASE("scatteringType: Lambertian D, Phong G (exponent 0: Lambertian, D), mirror and glass S [1 pt]") {
    const ps::Scene scene = everyKind();
    const struct {
        const char* material;
        VertexType want;
        const char* why;
    } cases[] = {
        {"white", VertexType::D, "a Lambertian (diffuse) material"},
        {"gloss", VertexType::G, "a Phong material of exponent 20: glossy, neither Lambertian nor delta"},
        {"flat", VertexType::D, "a Phong material of exponent 0, whose BRDF is albedo / pi: Lambertian"},
        {"chrome", VertexType::S, "a mirror: a delta BSDF"},
        {"glass", VertexType::S, "glass: a delta BSDF (reflection and refraction)"},
    };
    for (const auto& c : cases) {
        const VertexType got = ps::scatteringType(scene.materials[size_t(materialIndex(scene, c.material))]);
        CHECK_MESSAGE(got == c.want, "material '" << c.material << "' (" << c.why << "): expected " << letter(c.want)
                                                  << ", got " << letter(got));
    }
}

TEST_CASE("vertexType: x_0 is L whatever the light and its surface's material, the camera is E [2 pts]") {
    const ps::Scene scene = everyKind();
    const ps::PathVertex eye = ps::cameraVertex(scene), floor = surface(scene, "white", Vec3(0.3f, 0, 0.2f));
    // A point on a thin lens (lesson 11's second part: lesson 6's PathVertex::lens, as
    // cameraVertex(scene, z) makes it for a lens camera): no pinhole, no material, still the eye.
    ps::PathVertex lensPoint;
    lensPoint.sp.p = eye.sp.p + Vec3(0.03f, -0.02f, 0);
    lensPoint.sp.n = eye.sp.n;
    lensPoint.onCamera = true;
    const struct {
        const char* what;
        ps::PathVertex light;
    } lights[] = {
        {"an area light (its surface's material is the loader's black diffuse '(emitter)')", onAreaLight(scene, false)},
        {"an emitting white wall (material 'white', diffuse)", onAreaLight(scene, true)},
        {"a point light (no surface, no material: sp.material = -1)", onPointLight(scene)},
        {"the background (a direction at infinity, no material)", ps::backgroundVertex(scene, Vec3(0, 1, 0))},
    };
    for (const auto& l : lights) {
        const ps::Path x = {l.light, floor, eye};
        const VertexType t0 = ps::vertexType(scene, x, 0), t2 = ps::vertexType(scene, x, 2);
        CHECK_MESSAGE(t0 == VertexType::L, "x_0 on " << l.what
                                                     << ": expected L (the path's light, by its place "
                                                        "in the path), got "
                                                     << letter(t0));
        CHECK_MESSAGE(t2 == VertexType::E,
                      "x_2, the pinhole, of a path L D E: expected E (the eye, by its place), got " << letter(t2));
        const VertexType t1 = ps::vertexType(scene, x, 1);
        CHECK_MESSAGE(t1 == VertexType::D, "x_1 on the white floor: expected D, got " << letter(t1));
        const ps::Path y = {l.light, floor, lensPoint};
        const VertexType t2lens = ps::vertexType(scene, y, 2);
        CHECK_MESSAGE(t2lens == VertexType::E,
                      "x_2, a point on a thin lens (PathVertex::lens, not a pinhole), of a path L D E: expected E "
                      "(the eye, by its place, not by the pinhole flag), got "
                          << letter(t2lens));
    }
}

TEST_CASE("vertexType: a vertex in the middle of a path on a surface that emits scatters: D, not L [1 pt]") {
    const ps::Scene scene = everyKind();
    const int wall = lightIndex(scene, ps::LightKind::Area, true);
    // The lamp's light reaches the glowing white wall, which reflects it to the camera: the wall
    // is not the path's light (x_0 is the lamp), it is a diffuse bounce that happens to emit.
    const ps::Path x = {onAreaLight(scene, false), surface(scene, "white", Vec3(0, 1, 2), wall),
                        ps::cameraVertex(scene)};
    const VertexType t = ps::vertexType(scene, x, 1);
    CHECK_MESSAGE(t == VertexType::D,
                  "x_1 on the emitting white wall, between the lamp (x_0) and the eye: expected D "
                  "(it scatters the lamp's light; only x_0 is the path's light), got "
                      << letter(t));
    const ps::Path y = {onPointLight(scene), surface(scene, "chrome", Vec3(1, 0.5f, 0)),
                        surface(scene, "white", Vec3(0, 1, 2), wall), surface(scene, "gloss", Vec3(-1, 0.5f, 0)),
                        ps::cameraVertex(scene)};
    CHECK_MESSAGE(
        byVertex(scene, y) == "LSDGE",
        "point light, mirror, the emitting white wall, Phong, eye: expected LSDGE, got " << byVertex(scene, y));
}

TEST_CASE("pathString: the letters from the light to the eye (LSDE, LDSSE, LGE, LE) [2 pts]") {
    const ps::Scene scene = everyKind();
    const ps::PathVertex eye = ps::cameraVertex(scene);
    const ps::PathVertex floor = surface(scene, "white", Vec3(0.3f, 0, 0.2f));
    const ps::PathVertex mirror = surface(scene, "chrome", Vec3(1, 0.5f, 0));
    const ps::PathVertex glassIn = surface(scene, "glass", Vec3(0, 0.6f, 0)),
                         glassOut = surface(scene, "glass", Vec3(0, 0.4f, 0));
    const ps::PathVertex gloss = surface(scene, "gloss", Vec3(-1, 0.5f, 0));
    const struct {
        ps::Path x;
        const char* want;
        const char* what;
    } cases[] = {
        {{onAreaLight(scene, false), mirror, floor, eye}, "LSDE", "a caustic: the lamp, a mirror, the floor, the eye"},
        {{onPointLight(scene), floor, glassIn, glassOut, eye}, "LDSSE", "the floor seen through glass (in and out)"},
        {{ps::backgroundVertex(scene, Vec3(0, 1, 0)), gloss, eye}, "LGE", "the background on a Phong surface"},
        {{onAreaLight(scene, true), eye}, "LE", "an emitting wall seen directly"},
        {{onAreaLight(scene, false), floor, mirror, gloss, floor, eye}, "LDSGDE", "a longer path"},
    };
    for (const auto& c : cases) {
        const std::string got = ps::pathString(scene, c.x);
        std::string reversed(c.want);
        std::reverse(reversed.begin(), reversed.end());
        CHECK_MESSAGE(got == c.want, c.what << ": expected '" << c.want << "' (x_0, the light, first), got '" << got
                                            << "'"
                                            << (got == reversed ? " (reversed: Heckbert reads from the light)" : ""));
    }
}

TEST_CASE("pathString: the paths lesson 6 samples on the Cornell spheres, against the path's own flags [1 pt]") {
    // 600 paths of lengths 1-4 by every technique (lesson 6's sampleTechnique): each vertex's
    // expected letter from what lesson 6 says it is (x_0 on a light, x_k the pinhole, specular
    // by the delta flag, the rest diffuse: the Cornell spheres have no Phong).
    const ps::Scene scene = loadSceneAt("scenes/cornell-spheres.scene", 16, 16);
    ps::Rng rng(ps::testseed::seed(1101), 3);
    int checked = 0, wrong = 0;
    std::string first;
    for (int n = 0; n < 600; ++n) {
        const int k = 1 + n % 4, s = (n / 4) % (k + 1);
        const ps::TechniqueSample ts = ps::sampleTechnique(scene, k, s, rng);
        if (!ts.valid) continue;
        std::string want;
        for (size_t i = 0; i < ts.x.size(); ++i)
            want += i == 0 ? 'L' : i + 1 == ts.x.size() ? 'E' : ts.x[i].specular ? 'S' : 'D';
        const std::string got = ps::pathString(scene, ts.x);
        ++checked;
        if (got != want && wrong++ == 0) first = "expected '" + want + "', got '" + got + "'";
    }
    REQUIRE_MESSAGE(checked > 200, "lesson 6 sampled only " << checked << " valid paths");
    CHECK_MESSAGE(wrong == 0, wrong << " of " << checked << " sampled paths typed wrongly; the first: " << first);
}
