// A 5 x 7 bitmap font and labelled image strips (label.h).
#include "label.h"
#include <algorithm>
#include <cctype>
#include <cstdint>

namespace ps {

namespace {

struct Glyph {
    char c;
    uint8_t rows[kGlyphHeight];  // top row first; bit 4 is the left column, bit 0 the right one
};

// Drawn for this project: lower case, digits, the signs labels need, and the upper-case letters
// of Heckbert's path expressions.
// clang-format off
constexpr Glyph kFont[] = {
    {'0', {0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e}},
    {'1', {0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e}},
    {'2', {0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f}},
    {'3', {0x1f, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0e}},
    {'4', {0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02}},
    {'5', {0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e}},
    {'6', {0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e}},
    {'7', {0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e}},
    {'9', {0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c}},
    {'a', {0x00, 0x00, 0x0e, 0x01, 0x0f, 0x11, 0x0f}},
    {'b', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1e}},
    {'c', {0x00, 0x00, 0x0e, 0x10, 0x10, 0x11, 0x0e}},
    {'d', {0x01, 0x01, 0x0d, 0x13, 0x11, 0x11, 0x0f}},
    {'e', {0x00, 0x00, 0x0e, 0x11, 0x1f, 0x10, 0x0e}},
    {'f', {0x06, 0x09, 0x08, 0x1c, 0x08, 0x08, 0x08}},
    {'g', {0x00, 0x0f, 0x11, 0x11, 0x0f, 0x01, 0x0e}},
    {'h', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'i', {0x04, 0x00, 0x0c, 0x04, 0x04, 0x04, 0x0e}},
    {'j', {0x02, 0x00, 0x06, 0x02, 0x02, 0x12, 0x0c}},
    {'k', {0x10, 0x10, 0x12, 0x14, 0x18, 0x14, 0x12}},
    {'l', {0x0c, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e}},
    {'m', {0x00, 0x00, 0x1a, 0x15, 0x15, 0x11, 0x11}},
    {'n', {0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'o', {0x00, 0x00, 0x0e, 0x11, 0x11, 0x11, 0x0e}},
    {'p', {0x00, 0x00, 0x1e, 0x11, 0x1e, 0x10, 0x10}},
    {'q', {0x00, 0x00, 0x0d, 0x13, 0x0f, 0x01, 0x01}},
    {'r', {0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10}},
    {'s', {0x00, 0x00, 0x0e, 0x10, 0x0e, 0x01, 0x1e}},
    {'t', {0x08, 0x08, 0x1c, 0x08, 0x08, 0x09, 0x06}},
    {'u', {0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0d}},
    {'v', {0x00, 0x00, 0x11, 0x11, 0x11, 0x0a, 0x04}},
    {'w', {0x00, 0x00, 0x11, 0x11, 0x15, 0x15, 0x0a}},
    {'x', {0x00, 0x00, 0x11, 0x0a, 0x04, 0x0a, 0x11}},
    {'y', {0x00, 0x00, 0x11, 0x11, 0x0f, 0x01, 0x0e}},
    {'z', {0x00, 0x00, 0x1f, 0x02, 0x04, 0x08, 0x1f}},
    {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}},
    {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}},
    {',', {0x00, 0x00, 0x00, 0x00, 0x0c, 0x04, 0x08}},
    {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c}},
    {'=', {0x00, 0x00, 0x1f, 0x00, 0x1f, 0x00, 0x00}},
    {'-', {0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00}},
    {'+', {0x00, 0x04, 0x04, 0x1f, 0x04, 0x04, 0x00}},
    {':', {0x00, 0x0c, 0x0c, 0x00, 0x0c, 0x0c, 0x00}},
    {'/', {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00}},
    {'%', {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03}},
    {'_', {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1f}},
    {'[', {0x0e, 0x08, 0x08, 0x08, 0x08, 0x08, 0x0e}},
    {']', {0x0e, 0x02, 0x02, 0x02, 0x02, 0x02, 0x0e}},
    {'*', {0x00, 0x04, 0x15, 0x0e, 0x15, 0x04, 0x00}},
    {'|', {0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04}},
    {'?', {0x0e, 0x11, 0x01, 0x02, 0x04, 0x00, 0x04}},
    {'^', {0x04, 0x0a, 0x11, 0x00, 0x00, 0x00, 0x00}},
    // Heckbert's vertex types in path expressions (lesson 11) keep their upper case.
    {'L', {0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1f}},
    {'D', {0x1c, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1c}},
    {'G', {0x0e, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0f}},
    {'S', {0x0f, 0x10, 0x10, 0x0e, 0x01, 0x01, 0x1e}},
    {'E', {0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x1f}},
};
// clang-format on

const uint8_t* glyphRows(char c) {
    for (const Glyph& g : kFont)
        if (g.c == c) return g.rows;
    const char lower = char(std::tolower(static_cast<unsigned char>(c)));
    for (const Glyph& g : kFont)
        if (g.c == lower) return g.rows;
    return nullptr;
}

}  // namespace

int textWidth(const std::string& text, int scale) { return int(text.size()) * kGlyphAdvance * scale; }

int labelScale(int imageWidth) { return 1 + std::max(0, imageWidth) / 256; }

void drawText(Image& img, int x, int y, const std::string& text, int scale, const Color& ink, int maxX) {
    static constexpr uint8_t kBox[kGlyphHeight] = {0x1f, 0x11, 0x11, 0x11, 0x11, 0x11, 0x1f};
    const int right = std::min(maxX, img.width);
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == ' ') continue;
        const uint8_t* rows = glyphRows(text[i]);
        if (!rows) rows = kBox;
        const int gx = x + int(i) * kGlyphAdvance * scale;
        for (int r = 0; r < kGlyphHeight; ++r)
            for (int col = 0; col < kGlyphWidth; ++col) {
                if (!(rows[r] >> (kGlyphWidth - 1 - col) & 1)) continue;
                for (int sy = 0; sy < scale; ++sy)
                    for (int sx = 0; sx < scale; ++sx) {
                        const int px = gx + col * scale + sx, py = y + r * scale + sy;
                        if (px >= 0 && px < right && py >= 0 && py < img.height) img.at(px, py) = ink;
                    }
            }
    }
}

int stripFactor(int width) { return width <= 0 ? 1 : std::min(8, (kStripWidth + width - 1) / width); }

namespace {

// The label in lines of at most `width` pixels at font scale `scale`, broken at spaces; a word wider
// than a line is broken after its hyphens ("direct-" / "onesample"); empty if a piece is still wider.
std::vector<std::string> wrapLabel(const std::string& label, int width, int scale) {
    std::vector<std::string> lines;
    std::string line;
    const auto add = [&](const std::string& piece, const std::string& sep) {
        const std::string joined = line.empty() ? piece : line + sep + piece;
        if (textWidth(joined, scale) <= width) {
            line = joined;
        } else {
            lines.push_back(line);
            line = piece;
        }
    };
    size_t i = 0;
    while (i <= label.size()) {
        const size_t j = std::min(label.find(' ', i), label.size());
        const std::string word = label.substr(i, j - i);
        i = j + 1;
        if (word.empty()) continue;
        if (textWidth(word, scale) <= width) {
            add(word, " ");
            continue;
        }
        for (size_t a = 0; a < word.size();) {  // too wide: its pieces up to and including each '-'
            const size_t b = std::min(word.find('-', a), word.size() - 1) + 1;
            const std::string piece = word.substr(a, b - a);
            if (textWidth(piece, scale) > width) return {};
            add(piece, a == 0 ? " " : "");
            a = b;
        }
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

}  // namespace

Image labelledStrip(const std::vector<Image>& images, const std::vector<std::string>& labels, const Color& ink) {
    int w0 = 0, narrowest = 1 << 30;
    for (const Image& im : images) {
        w0 += im.width;
        narrowest = std::min(narrowest, im.width);
    }
    const int k = stripFactor(w0);
    const int cell = images.empty() ? 0 : narrowest * k;
    // The largest font scale at which every label fits its cell in at most two lines (its glyphs at
    // most a seventh of the cell's width high), or in one line if that is not much smaller, or in
    // three if that is much larger (seven cells with labels like "direct-onesample 16 spp").
    const auto largestScale = [&](size_t maxLines) {
        for (int scale = std::max(1, cell / (7 * kGlyphHeight)); scale > 1; --scale) {
            bool fits = true;
            for (size_t i = 0; i < labels.size() && fits; ++i) {
                const std::vector<std::string> l = wrapLabel(labels[i], cell - 4 * scale, scale);
                fits = !(l.empty() && !labels[i].empty()) && l.size() <= maxLines;
            }
            if (fits) return scale;
        }
        return 1;
    };
    const int twoLines = largestScale(2), oneLine = largestScale(1), threeLines = largestScale(3);
    const int scale = 5 * oneLine >= 4 * twoLines ? oneLine : 4 * threeLines >= 5 * twoLines ? threeLines : twoLines;
    std::vector<std::vector<std::string>> lines(labels.size());
    for (size_t i = 0; i < labels.size(); ++i) lines[i] = wrapLabel(labels[i], cell - 4 * scale, scale);
    size_t rows = 1;
    for (size_t i = 0; i < labels.size(); ++i) {
        if (lines[i].empty() && !labels[i].empty()) lines[i] = {labels[i]};  // too long at any scale: cut
        rows = std::max(rows, lines[i].size());
    }
    const int pad = 2 * scale, lineHeight = (kGlyphHeight + 2) * scale;
    const int band = int(rows) * lineHeight - 2 * scale + 2 * pad;
    int h = 0;
    for (const Image& im : images) h = std::max(h, im.height * k);
    Image out(w0 * k, h + band);
    int x0 = 0;
    for (size_t n = 0; n < images.size(); ++n) {
        const Image& im = images[n];
        if (n < lines.size())
            for (size_t l = 0; l < lines[n].size(); ++l)
                drawText(out, x0 + pad, pad + int(l) * lineHeight, lines[n][l], scale, ink, x0 + im.width * k - pad);
        for (int y = 0; y < im.height * k; ++y)
            for (int x = 0; x < im.width * k; ++x) out.at(x0 + x, band + y) = im.at(x / k, y / k);
        x0 += im.width * k;
    }
    return out;
}

}  // namespace ps
