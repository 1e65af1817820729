#include "image.h"
#include <cstdio>
#include <cstring>
#include <fstream>
#include "errors.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_HDR
#include <stb_image.h>

namespace ps {

namespace {
std::string extensionOf(const std::string& path) {
    size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}
bool littleEndianHost() { uint16_t x = 1; unsigned char b; std::memcpy(&b, &x, 1); return b == 1; }
}  // namespace

void writePFM(const std::string& path, const Image& img) {
    std::ofstream f(path, std::ios::binary);
    if (!f) throw InputError(path, 0, "cannot open for writing");
    // Header: "PF" (colour), size, scale < 0 means little-endian. Rows go bottom to top.
    f << "PF\n" << img.width << " " << img.height << "\n" << (littleEndianHost() ? "-1.0" : "1.0") << "\n";
    for (int y = img.height - 1; y >= 0; --y)
        f.write(reinterpret_cast<const char*>(&img.at(0, y)), sizeof(Color) * size_t(img.width));
    if (!f) throw InputError(path, 0, "write failed");
}

Image readPFM(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw InputError(path, 0, "cannot open file (does it exist?)");
    std::string magic;
    int w = 0, h = 0;
    double scale = 0.0;
    if (!(f >> magic >> w >> h >> scale) || magic != "PF")
        throw InputError(path, 0, "not a colour PFM file (expected header 'PF width height scale')");
    if (w <= 0 || h <= 0 || w > 1 << 16 || h > 1 << 16 || scale == 0.0 || !std::isfinite(scale))
        throw InputError(path, 0, "bad PFM header (size " + std::to_string(w) + "x" + std::to_string(h) + ")");
    f.get();   // the single whitespace after the scale
    const bool fileLE = scale < 0.0;
    Image img(w, h);
    for (int y = h - 1; y >= 0; --y) {
        f.read(reinterpret_cast<char*>(&img.at(0, y)), sizeof(Color) * size_t(w));
        if (!f) throw InputError(path, 0, "file ends before all pixels were read");
    }
    if (fileLE != littleEndianHost()) {
        for (Color& c : img.pixels)
            for (int k = 0; k < 3; ++k) {
                unsigned char b[4];
                std::memcpy(b, static_cast<const void*>(&c[k]), 4);
                std::swap(b[0], b[3]); std::swap(b[1], b[2]);
                std::memcpy(static_cast<void*>(&c[k]), b, 4);
            }
    }
    return img;
}

void writeHDR(const std::string& path, const Image& img) {
    if (!stbi_write_hdr(path.c_str(), img.width, img.height, 3, &img.pixels[0].r))
        throw InputError(path, 0, "cannot write .hdr file");
}

Image readHDR(const std::string& path) {
    int w, h, n;
    float* data = stbi_loadf(path.c_str(), &w, &h, &n, 3);
    if (!data) throw InputError(path, 0, std::string("cannot read .hdr file: ") + stbi_failure_reason());
    Image img(w, h);
    std::memcpy(static_cast<void*>(img.pixels.data()), data, sizeof(float) * 3 * size_t(w) * h);
    stbi_image_free(data);
    return img;
}

void writePNG(const std::string& path, const Image& img, float exposure) {
    std::vector<unsigned char> bytes(size_t(img.width) * img.height * 3);
    const float scale = std::exp2(exposure);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            float v = img.pixels[i][k] * scale;
            v = std::isfinite(v) ? glm::clamp(v, 0.0f, 1.0f) : 0.0f;
            v = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;   // sRGB
            bytes[3 * i + k] = static_cast<unsigned char>(std::lround(v * 255.0f));
        }
    if (!stbi_write_png(path.c_str(), img.width, img.height, 3, bytes.data(), img.width * 3))
        throw InputError(path, 0, "cannot write PNG file");
}

void writeImage(const std::string& path, const Image& img) {
    const std::string ext = extensionOf(path);
    if (ext == "pfm") writePFM(path, img);
    else if (ext == "hdr") writeHDR(path, img);
    else if (ext == "png") writePNG(path, img);
    else throw InputError(path, 0, "unknown image type '." + ext + "' (use .png, .pfm or .hdr)");
}

Image readImage(const std::string& path) {
    const std::string ext = extensionOf(path);
    if (ext == "pfm") return readPFM(path);
    if (ext == "hdr") return readHDR(path);
    throw InputError(path, 0, "cannot read '." + ext + "' images (use .pfm or .hdr)");
}

}  // namespace ps
