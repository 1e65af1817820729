// Fuzz target: the Radiance .hdr (RGBE) reader (framework/image.cpp).
#include "fuzz_input.h"
#include "image.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string path = psfuzz::writeScratch("image.hdr", data, size);
    psfuzz::expectOnlyInputError([&] { (void)ps::readHDR(path); });
    return 0;
}
