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

// All writers and readers throw InputError (see errors.h) naming the file on failure. Readers
// check every size in a header before they allocate: against the file's length, against
// kMaxImagePixels, and, given width and height > 0, against the size the caller expects (a
// reference for a render), so that no file makes them decode more than what is asked for (a
// run-length .hdr of 50 MB can describe 9 GB of pixels).
constexpr long long kMaxImagePixels = 1LL << 26;  // 805 MB of float pixels; 16 renders of the largest size
void writePFM(const std::string& path, const Image& img);
Image readPFM(const std::string& path, int width = 0, int height = 0);
void writeHDR(const std::string& path, const Image& img);
Image readHDR(const std::string& path, int width = 0, int height = 0);
// OpenEXR, RGB 32-bit float (tinyexr): written, not read.
void writeEXR(const std::string& path, const Image& img);
// Tone mapping: x * 2^exposure, clamped to [0,1], sRGB transfer curve, 8 bits.
void writePNG(const std::string& path, const Image& img, float exposure = 0.0f);

// Writes by extension (.pfm, .hdr, .png, .exr); reads .pfm or .hdr.
void writeImage(const std::string& path, const Image& img);
// The extensions writeImage knows, lower case with the dot: {".png", ".pfm", ".hdr"}.
const std::vector<std::string>& imageExtensions();
Image readImage(const std::string& path, int width = 0, int height = 0);

}  // namespace ps
