// Scene files as text, for tests that derive variants of a shipped scene: read a file, edit
// words and lines, move or scale everything in it. Defined in scene_text.cpp (compiled once into
// test_support: string streams and the like stay out of every test's translation unit).
#pragma once
#include <string>

namespace ps::scenetext {

// The whole file; fails the test (REQUIRE) if it cannot be read.
std::string readText(const std::string& path);

// `text` with every occurrence of `from` replaced by `to` (plain text, no patterns). Fails the
// test (REQUIRE) when `from` does not occur: a variant that silently equals the original would
// let the test pass for the wrong reason.
std::string replaceAll(std::string text, const std::string& from, const std::string& to);

// `text` with every line whose first word is `keyword` replaced by `line`; REQUIRE: one at least.
std::string replaceLines(const std::string& text, const std::string& keyword, const std::string& line);

// `text` with the camera's "resolution W H" set to width x height; REQUIRE: it has one.
std::string withResolution(const std::string& text, int width, int height);

// The scene text with every point p replaced by s * p + t (camera eye and target, corners of
// triangles and quads, sphere centres and radii, point light positions; a thin lens's radius and
// focus distance times s), point light intensities multiplied by s^2 (the same irradiance at the
// scaled distances), and the resolution set to res x res. Directions (the camera's up) and everything else stay, so the
// image is the same up to rounding.
std::string transformScene(const std::string& text, double s, double t, int res);

}  // namespace ps::scenetext
