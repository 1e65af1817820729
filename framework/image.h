// Images and their files: PFM (exact floats, for tests and metrics), PNG (tone-mapped sRGB,
// for people), Radiance .hdr (RGBE, lossy, on request). Row 0 is the top row.
#pragma once
#include <string>
#include <vector>
#include "vecmath.h"

namespace ps {

struct Image {
    int width = 0, height = 0;
    std::vector<Color> pixels;
    Image() = default;
    Image(int w, int h, const Color& fill = Color(0.0f)) : width(w), height(h), pixels(size_t(w) * h, fill) {}
    Color& at(int x, int y) { return pixels[size_t(y) * width + x]; }
    const Color& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

// All writers and readers throw InputError (see errors.h) naming the file on failure.
void writePFM(const std::string& path, const Image& img);
Image readPFM(const std::string& path);
void writeHDR(const std::string& path, const Image& img);
Image readHDR(const std::string& path);
// OpenEXR, RGB 32-bit float (tinyexr): written, not read.
void writeEXR(const std::string& path, const Image& img);
// Tone mapping: x * 2^exposure, clamped to [0,1], sRGB transfer curve, 8 bits.
void writePNG(const std::string& path, const Image& img, float exposure = 0.0f);

// Writes by extension (.pfm, .hdr, .png, .exr); reads .pfm or .hdr.
void writeImage(const std::string& path, const Image& img);
// The extensions writeImage knows, lower case with the dot: {".png", ".pfm", ".hdr"}.
const std::vector<std::string>& imageExtensions();
Image readImage(const std::string& path);

}  // namespace ps
