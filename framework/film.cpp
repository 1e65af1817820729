#include "film.h"

namespace ps {

void Film::addIteration(const Image& it) {
    for (size_t i = 0; i < sum_.size(); ++i) {
        const DColor v(it.pixels[i]);
        sum_[i] += v;
        sumSq_[i] += v * v;
    }
    ++iterations_;
}

Image Film::mean() const {
    Image img(width_, height_);
    if (iterations_ == 0) return img;
    for (size_t i = 0; i < sum_.size(); ++i) img.pixels[i] = Color(sum_[i] / double(iterations_));
    return img;
}

Image Film::varianceOfMean() const {
    Image img(width_, height_);
    const double n = iterations_;
    if (n < 2) return img;
    for (size_t i = 0; i < sum_.size(); ++i) {
        DColor s2 = (sumSq_[i] - sum_[i] * sum_[i] / n) / (n - 1.0);  // sample variance
        img.pixels[i] = Color(glm::max(s2, DColor(0.0)) / n);
    }
    return img;
}

void SplatBuffer::splat(size_t task, const Vec2& raster, const Color& c, SampleStats& stats) {
    const Color v = checkSample(c, stats);
    if (isBlack(v)) return;
    // Outside the image (or NaN): dropped. Truncation would move (-1, 0) onto pixel 0, and
    // clamping alone would pile everything right of or below the image onto the last pixel;
    // only a point exactly on the far edge (x = width, by rounding) goes to the last pixel.
    if (!(raster.x >= 0.0f && raster.x <= width_ && raster.y >= 0.0f && raster.y <= height_)) return;
    const int x = std::min(width_ - 1, static_cast<int>(raster.x));
    const int y = std::min(height_ - 1, static_cast<int>(raster.y));
    lists_[task].splats.emplace_back(static_cast<uint32_t>(y * width_ + x), v);
}

void SplatBuffer::resolve(Image& img) {
    for (List& list : lists_) {
        for (const auto& [pixel, c] : list.splats) img.pixels[pixel] += c;
        list.splats.clear();
    }
}

}  // namespace ps
