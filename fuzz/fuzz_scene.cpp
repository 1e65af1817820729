// Fuzz target: the scene file format (framework/scene_loader.cpp), from text to a finished
// scene (BVH, lights, capabilities).
#include "fuzz_input.h"
#include "scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    psfuzz::expectOnlyInputError([&] { (void)ps::parseScene(text, "fuzz.scene"); });
    return 0;
}
