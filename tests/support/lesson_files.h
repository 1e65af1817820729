// The repository's files as the graded tests read them: a path in the source tree, a file's
// text, a shipped scene at test resolution. The source and build trees' paths come from
// test_paths.cpp; each lesson's lessonNN.h brings these names into its namespace.
#pragma once
#include <cstdlib>
#include <string>
#include "scene_loader.h"
#include "scene_text.h"

namespace ps::testfiles {

// The source tree (the repository or the handout) and the build tree (test_paths.cpp).
const char* sourceDir();
const char* binaryDir();

// The environment's PATHSPACE_TEST_SOURCE_DIR, when set, stands for the source tree: the grader
// points it at its prepared tree's data/ (tools/grade), which holds the files tests read.
inline std::string sourcePath(const std::string& rel) {
    const char* dir = std::getenv("PATHSPACE_TEST_SOURCE_DIR");
    return std::string(dir && *dir ? dir : sourceDir()) + "/" + rel;
}

// The whole file; fails the test (REQUIRE) if it cannot be read.
inline std::string readText(const std::string& path) { return scenetext::readText(path); }

// A scene file of the repository at width x height pixels (its 'resolution' replaced), so that
// the tests and the documented reference commands (`sed` on the same file) see the same scene.
inline Scene loadSceneAt(const std::string& rel, int width, int height) {
    const std::string path = sourcePath(rel);
    const std::string text = scenetext::withResolution(readText(path), width, height);
    return parseScene(text, path);
}

}  // namespace ps::testfiles
