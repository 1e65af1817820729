// Reads the scene format (scenes/README.md describes it) and OBJ meshes (tinyobjloader).
// Every problem throws InputError("file:line: problem").
#pragma once
#include <string>
#include "scene.h"

namespace ps {

// Loads and finalizes the scene file at path. Meshes are found relative to its folder.
Scene loadScene(const std::string& path);

// The same for scene text already in memory; `path` names it in messages and locates meshes.
Scene parseScene(const std::string& text, const std::string& path);

}  // namespace ps
