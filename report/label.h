// Text drawn into an image: the labels on the equal-time strip of `pathspace converge` and on
// the cells of `pathspace pyramid`, so that a figure says what each image is. A 5 x 7 pixel font
// of lower-case letters, digits, the signs labels use and the upper-case L, D, G, S, E of
// Heckbert's path expressions (lesson 11); any other upper-case letter is drawn as its lower case,
// any other character as an empty box. Each font pixel becomes scale x scale pixels.
#pragma once
#include <string>
#include <vector>
#include "image.h"

namespace ps {

constexpr int kGlyphWidth = 5, kGlyphHeight = 7, kGlyphAdvance = 6;  // font pixels

// Width of the text in image pixels (6 font pixels per character, the last one's gap included).
int textWidth(const std::string& text, int scale);
// Draws the text with its top-left corner at (x, y); pixels beyond maxX (exclusive) or outside the
// image are not drawn. ink: the colour of the glyphs' pixels.
void drawText(Image& img, int x, int y, const std::string& text, int scale, const Color& ink, int maxX = 1 << 30);
// A label size that reads at the image's width: 1 font pixel per image pixel below 256 pixels,
// then one more per 256.
int labelScale(int imageWidth);

// The images side by side, left to right, each under its label (a band of text above it, on the
// background colour). ink: the text's colour (for a PNG written with exposure E, 2^-E is white).
// The strip is made at slide resolution, so that its labels read on a lecture slide: images
// narrower together than kStripWidth are enlarged by a whole factor (each pixel a square of
// pixels, no filtering), and the labels take the largest font that fits their cell (a label may
// wrap at spaces, or a word too wide for the cell after its hyphens, onto a second line, or a third
// if that makes the font much larger), up to a glyph height of a seventh of the cell's width.
constexpr int kStripWidth = 1200;
Image labelledStrip(const std::vector<Image>& images, const std::vector<std::string>& labels, const Color& ink);
// The whole factor labelledStrip enlarges images of total width `width` by.
int stripFactor(int width);

}  // namespace ps
