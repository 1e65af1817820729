// Sampling helpers of the framework: the warps of lesson 1 (warps.h) and a discrete
// distribution for choosing lights by power and triangles by area.
#pragma once
#include <vector>
#include "vecmath.h"
#include "warps.h"

namespace ps {

// The u to give the cosine-weighted warp (sampleCosineHemisphere, lesson 1, Eqs. 1.10-1.11)
// when its sample must be usable. The concentric map sends a coordinate exactly 0 (a or b = -1,
// the larger in magnitude) to the disk's rim: cos(theta) = 0, pdf 0, and the sample is lost (a
// path ends there: up to 2 x 2^-24 = 1.2e-7 per bounce, 8e-8 with lesson 1's map, whose rounding
// saves a third; 0.8 % of the paths at albedo 1 and maximum depth 1e5). Such a coordinate stands for the sampler's cell [0, 2^-24) (Rng::uniform gives
// multiples of 2^-24); it is replaced by the next grid point inside the disk by a margin rounding
// cannot close, kOffRim. Every other u is returned unchanged, and the students' warps (whose map
// may differ) see only values the sampler could give them anyway.
constexpr float kOffRim = 0x1p-20f;
inline Vec2 cosineWarpU(Vec2 u) {
    if (u.x < kOffRim * 0x1p-4f) u.x = kOffRim;
    if (u.y < kOffRim * 0x1p-4f) u.y = kOffRim;
    return u;
}

// A discrete distribution over n weights (light selection by power, triangles by area).
class Distribution1D {
public:
    Distribution1D() = default;
    explicit Distribution1D(const std::vector<double>& weights) {
        cdf_.assign(weights.size() + 1, 0.0);
        for (size_t i = 0; i < weights.size(); ++i) cdf_[i + 1] = cdf_[i] + std::max(0.0, weights[i]);
        total_ = cdf_.back();
        if (total_ > 0.0)
            for (double& c : cdf_) c /= total_;
    }
    size_t size() const { return cdf_.empty() ? 0 : cdf_.size() - 1; }
    double total() const { return total_; }
    // Picks index i with probability w_i / sum w; u in [0, 1).
    size_t sample(float u) const {
        size_t lo = 0, hi = size();  // find i with cdf[i] <= u < cdf[i+1]
        while (hi - lo > 1) {
            size_t mid = (lo + hi) / 2;
            (cdf_[mid] <= u ? lo : hi) = mid;
        }
        return lo;
    }
    float pmf(size_t i) const { return i < size() ? static_cast<float>(cdf_[i + 1] - cdf_[i]) : 0.0f; }

private:
    std::vector<double> cdf_;
    double total_ = 0.0;
};

}  // namespace ps
