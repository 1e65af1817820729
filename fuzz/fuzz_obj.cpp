// Fuzz target: OBJ meshes and their MTL files, through the scene's 'mesh' line. The input is an
// OBJ file, optionally followed by a line "#MTL" and the text of fuzz.mtl (which the OBJ can
// name with "mtllib fuzz.mtl").
#include <cstring>
#include "fuzz_input.h"
#include "scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string all(reinterpret_cast<const char*>(data), size);
    const size_t split = all.find("\n#MTL\n");
    const std::string obj = all.substr(0, split);
    const std::string mtl = split == std::string::npos ? std::string() : all.substr(split + 6);
    const std::string objPath =
        psfuzz::writeScratch("mesh.obj", reinterpret_cast<const uint8_t*>(obj.data()), obj.size());
    // The MTL goes next to the OBJ under the name the OBJ uses.
    const std::string dir = objPath.substr(0, objPath.find_last_of('/') + 1);
    std::ofstream(dir + "fuzz.mtl", std::ios::binary) << mtl;
    const std::string scene =
        "camera eye 0 0 -5  target 0 0 0  fov 40  resolution 8 8\n"
        "mesh " +
        objPath + (split == std::string::npos ? " emission 1 1 1\n" : "\n");
    psfuzz::expectOnlyInputError([&] { (void)ps::parseScene(scene, "fuzz.scene"); });
    return 0;
}
