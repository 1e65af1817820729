#include "image.h"
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include "errors.h"
#include "file_writer.h"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
#include <tinyexr.h>

namespace ps {

namespace {
std::string extensionOf(const std::string& path) {
    size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find('/', dot) != std::string::npos) return "";
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}
bool littleEndianHost() {
    uint16_t x = 1;
    unsigned char b;
    std::memcpy(&b, &x, 1);
    return b == 1;
}

// Readers check a header's size against the bytes the file really has before they allocate:
// a 24-byte file must not make them ask for gigabytes.
constexpr int kMaxImageSide = 1 << 16;

// The header's size w x h against the limits and against the size the caller expects (0: any),
// before anything is allocated; InputError naming the file otherwise.
void checkHeaderSize(const std::string& path, long long w, long long h, int expectW, int expectH) {
    const std::string size = std::to_string(w) + "x" + std::to_string(h);
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
        throw InputError(
            path, 0,
            "the header says " + size + " pixels (each side must be 1 to " + std::to_string(kMaxImageSide) + ")");
    if (expectW > 0 && expectH > 0 && (w != expectW || h != expectH))
        throw InputError(
            path, 0,
            "the image is " + size + " pixels, expected " + std::to_string(expectW) + "x" + std::to_string(expectH));
    if (w * h > kMaxImagePixels)
        throw InputError(path, 0,
                         "the header says " + size + " pixels, more than the " + std::to_string(kMaxImagePixels) +
                             " pathspace reads");
}

// The bytes of f from its current position to its end (f is left where it was).
uint64_t bytesLeft(std::ifstream& f) {
    const std::streampos here = f.tellg();
    f.seekg(0, std::ios::end);
    const std::streampos end = f.tellg();
    f.seekg(here);
    return here >= 0 && end >= here ? uint64_t(end - here) : 0;
}
}  // namespace

void writePFM(const std::string& path, const Image& img) {
    FileWriter f(path);
    // Header: "PF" (colour), size, scale < 0 means little-endian. Rows go bottom to top.
    f.write("PF\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n" +
            (littleEndianHost() ? "-1.0" : "1.0") + "\n");
    for (int y = img.height - 1; y >= 0; --y) f.write(&img.at(0, y), sizeof(Color) * size_t(img.width));
    f.close();
}

Image readPFM(const std::string& path, int expectW, int expectH) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw InputError(path, 0, "cannot open file (does it exist?)");
    std::string magic;
    int w = 0, h = 0;
    double scale = 0.0;
    if (!(f >> magic >> w >> h >> scale) || magic != "PF")
        throw InputError(path, 0, "not a colour PFM file (expected header 'PF width height scale')");
    if (w <= 0 || h <= 0 || w > 1 << 16 || h > 1 << 16 || scale == 0.0 || !std::isfinite(scale))
        throw InputError(path, 0, "bad PFM header (size " + std::to_string(w) + "x" + std::to_string(h) + ")");
    f.get();  // the single whitespace after the scale
    const bool fileLE = scale < 0.0;
    const uint64_t need = uint64_t(w) * uint64_t(h) * sizeof(Color), have = bytesLeft(f);
    if (have < need)
        throw InputError(path, 0,
                         "the header says " + std::to_string(w) + "x" + std::to_string(h) + " pixels (" +
                             std::to_string(need) + " bytes) but the file has only " + std::to_string(have) +
                             " bytes of pixels (truncated?)");
    checkHeaderSize(path, w, h, expectW, expectH);
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
                std::swap(b[0], b[3]);
                std::swap(b[1], b[2]);
                std::memcpy(static_cast<void*>(&c[k]), b, 4);
            }
    }
    return img;
}

namespace {
// stb's writers hand their bytes to a callback (a PNG at once, a .hdr a scanline at a time):
// this one writes them through a FileWriter and keeps the first failure, which the caller throws
// once stb has returned (an exception must not cross stb's C code).
struct StbTarget {
    FileWriter file;
    std::string error;
    explicit StbTarget(const std::string& path) : file(path) {}
    static void write(void* context, void* data, int size) {
        StbTarget& t = *static_cast<StbTarget*>(context);
        if (!t.error.empty() || size <= 0) return;
        try {
            t.file.write(data, size_t(size));
        } catch (const InputError& e) { t.error = e.what(); }
    }
    void finish(bool encoded, const std::string& what) {
        if (!error.empty()) throw InputError(error);
        if (!encoded) throw InputError(file.path(), 0, "cannot encode the " + what + " image");
        file.close();
    }
};
}  // namespace

void writeHDR(const std::string& path, const Image& img) {
    StbTarget target(path);
    const int ok = stbi_write_hdr_to_func(&StbTarget::write, &target, img.width, img.height, 3, &img.pixels[0].r);
    target.finish(ok != 0, ".hdr");
}

// Radiance .hdr (RGBE), our own reader: the header lines up to an empty line, the size line
// "-Y height +X width" (rows top to bottom, as writeHDR writes them), then per scanline either
// the run-length encoding (2 2 w/256 w%256, then each of the 4 channels as runs: a count byte
// c > 128 repeats the next byte c - 128 times, 0 < c <= 128 copies c bytes) or flat 4-byte
// pixels. Every count and size is checked against the file, so a truncated or hostile file
// gets an error, never a hang or a huge allocation.
Image readHDR(const std::string& path, int expectW, int expectH) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw InputError(path, 0, "cannot open file (does it exist?)");
    auto fail = [&](const std::string& problem) -> void {
        throw InputError(path, 0, "not a readable .hdr file: " + problem);
    };
    std::string line;
    if (!std::getline(f, line) || line.rfind("#?", 0) != 0) fail("it does not start with '#?RADIANCE'");
    bool rgbe = true;
    for (int n = 0;; ++n) {
        if (!std::getline(f, line)) fail("the header does not end (no empty line before the size)");
        if (line.empty()) break;
        if (line.rfind("FORMAT=", 0) == 0) rgbe = line == "FORMAT=32-bit_rle_rgbe";
        if (n > 1000 || line.size() > 4096) fail("header too long");
    }
    if (!rgbe) fail("only FORMAT=32-bit_rle_rgbe is supported");
    if (!std::getline(f, line)) fail("no size line");
    char ya[3] = {}, xa[3] = {};
    long long h = 0, w = 0;
    char extra = 0;
    if (std::sscanf(line.c_str(), "%2s %lld %2s %lld %c", ya, &h, xa, &w, &extra) != 4 || std::string(ya) != "-Y" ||
        std::string(xa) != "+X")
        fail("size line '" + line.substr(0, 40) +
             "' is not '-Y height +X width' (other orientations are not supported)");
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
        fail("size " + std::to_string(w) + "x" + std::to_string(h) + " (each side must be 1 to " +
             std::to_string(kMaxImageSide) + ")");
    // The smallest possible scanline: run-length encoded, every channel in runs of 127.
    const bool rle = w >= 8 && w < 32768;
    const uint64_t minLine = rle ? 4 + 4 * 2 * uint64_t((w + 126) / 127) : 4 * uint64_t(w);
    if (bytesLeft(f) < minLine * uint64_t(h))
        fail("the size says " + std::to_string(w) + "x" + std::to_string(h) + " but the file is too short for it");
    checkHeaderSize(path, w, h, expectW, expectH);
    // The most bytes w x h pixels can take (a scanline in copies of at most 128 bytes per channel,
    // or flat): what follows is never read, however large the file.
    const uint64_t maxLine = std::max<uint64_t>(4 + 4 * (uint64_t(w) + uint64_t((w + 127) / 128)), 4 * uint64_t(w));
    std::vector<unsigned char> data(size_t(std::min(bytesLeft(f), maxLine * uint64_t(h))));
    if (!f.read(reinterpret_cast<char*>(data.data()), std::streamsize(data.size())))
        fail("the file could not be read to the end of its pixels");
    size_t at = 0;
    auto next = [&]() -> unsigned char {
        if (at >= data.size()) fail("the file ends inside the pixels (truncated?)");
        return data[at++];
    };
    Image img{int(w), int(h)};
    std::vector<unsigned char> scan(4 * size_t(w));
    for (int y = 0; y < h; ++y) {
        const bool encoded = rle && at + 4 <= data.size() && data[at] == 2 && data[at + 1] == 2 &&
                             ((data[at + 2] << 8) | data[at + 3]) == w;
        if (encoded) {
            at += 4;
            for (int c = 0; c < 4; ++c) {
                for (long long x = 0; x < w;) {
                    const unsigned count = next();
                    if (count == 0) fail("a run of length 0 in scanline " + std::to_string(y));
                    const unsigned n = count > 128 ? count - 128 : count;
                    if (x + n > w) fail("a run goes past the end of scanline " + std::to_string(y));
                    if (count > 128) {
                        const unsigned char v = next();
                        for (unsigned i = 0; i < n; ++i) scan[4 * size_t(x++) + c] = v;
                    } else {
                        for (unsigned i = 0; i < n; ++i) scan[4 * size_t(x++) + c] = next();
                    }
                }
            }
        } else {
            for (size_t i = 0; i < scan.size(); ++i) scan[i] = next();
        }
        for (int x = 0; x < w; ++x) {
            const unsigned char* p = &scan[4 * size_t(x)];
            const float s = p[3] == 0 ? 0.0f : std::ldexp(1.0f, int(p[3]) - (128 + 8));
            img.at(x, y) = Color(p[0] * s, p[1] * s, p[2] * s);
        }
    }
    return img;
}

void writePNG(const std::string& path, const Image& img, float exposure) {
    std::vector<unsigned char> bytes(size_t(img.width) * img.height * 3);
    const float scale = std::exp2(exposure);
    for (size_t i = 0; i < img.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            float v = img.pixels[i][k] * scale;
            v = std::isfinite(v) ? glm::clamp(v, 0.0f, 1.0f) : 0.0f;
            v = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;  // sRGB
            bytes[3 * i + k] = static_cast<unsigned char>(std::lround(v * 255.0f));
        }
    StbTarget target(path);
    const int ok =
        stbi_write_png_to_func(&StbTarget::write, &target, img.width, img.height, 3, bytes.data(), img.width * 3);
    target.finish(ok != 0, "PNG");
}

// OpenEXR through tinyexr (Debian libtinyexr-dev): RGB, 32-bit float per channel (the pixels
// exactly, like PFM), ZIP-compressed; opens in tev and the other HDR viewers. Encoded in memory
// by SaveEXRImageToMemory (its file writer checks neither fwrite nor fclose) and written through
// FileWriter, with header arrays we own (the simpler SaveEXR of tinyexr 1.0.1 leaks its
// channel list on every call). Channels in the order viewers expect: B, G, R.
void writeEXR(const std::string& path, const Image& img) {
    const size_t n = size_t(img.width) * img.height;
    std::vector<float> planes[3] = {std::vector<float>(n), std::vector<float>(n), std::vector<float>(n)};
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) planes[2 - k][i] = img.pixels[i][k];  // B, G, R
    float* channelData[3] = {planes[0].data(), planes[1].data(), planes[2].data()};
    EXRImage image;
    InitEXRImage(&image);
    image.num_channels = 3;
    image.width = img.width;
    image.height = img.height;
    image.images = reinterpret_cast<unsigned char**>(channelData);
    EXRHeader header;
    InitEXRHeader(&header);
    EXRChannelInfo channels[3] = {};
    const char* names[3] = {"B", "G", "R"};
    for (int k = 0; k < 3; ++k) std::snprintf(channels[k].name, sizeof channels[k].name, "%s", names[k]);
    int pixelTypes[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    int requested[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    header.num_channels = 3;
    header.channels = channels;
    header.pixel_types = pixelTypes;
    header.requested_pixel_types = requested;
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    FileWriter file(path);
    const char* err = nullptr;
    unsigned char* bytes = nullptr;
    const size_t size = SaveEXRImageToMemory(&image, &header, &bytes, &err);
    if (size == 0 || !bytes) {
        const std::string why = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        std::free(bytes);
        throw InputError(path, 0, "cannot encode the EXR image (" + why + ")");
    }
    try {
        file.write(bytes, size);
    } catch (...) {
        std::free(bytes);
        throw;
    }
    std::free(bytes);
    file.close();
}

const std::vector<std::string>& imageExtensions() {
    static const std::vector<std::string> extensions = {".png", ".pfm", ".hdr", ".exr"};
    return extensions;
}

void writeImage(const std::string& path, const Image& img) {
    const std::string ext = extensionOf(path);
    if (ext == "pfm") writePFM(path, img);
    else if (ext == "hdr") writeHDR(path, img);
    else if (ext == "png") writePNG(path, img);
    else if (ext == "exr") writeEXR(path, img);
    else throw InputError(path, 0, "unknown image type '." + ext + "' (use .png, .pfm, .hdr or .exr)");
}

Image readImage(const std::string& path, int width, int height) {
    const std::string ext = extensionOf(path);
    if (ext == "pfm") return readPFM(path, width, height);
    if (ext == "hdr") return readHDR(path, width, height);
    throw InputError(path, 0, "cannot read '." + ext + "' images (use .pfm or .hdr)");
}

}  // namespace ps
