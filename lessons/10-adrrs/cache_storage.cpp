// Lesson 10 — the adjoint cache's storage (plumbing: read it, nothing to write here): a sum and a
// count per entry (and a sum of squares for the estimate's relative error); an entry's estimate
// is the mean of the samples the pre-pass gave it (Eq. 10.8). The estimate and whether it is
// reliable are brought up to date with every sample, so that a lookup while rendering reads them.
// Where a vertex lands (AdjointCache::cell, AdjointCache::side) is yours: adjoint_cache.cpp.
#include <algorithm>
#include <cmath>
#include "10-adrrs/adrrs.h"

namespace ps {

AdjointCache::AdjointCache(const AABB& bounds, int resolution)
    : bounds_(bounds),
      res_(resolution),
      sum_(size_t(resolution) * resolution * resolution * kCacheSides, DColor(0.0)),
      sumSq_(sum_.size(), 0.0),
      count_(sum_.size(), 0),
      exact_(sum_.size(), 0),
      mean_(sum_.size(), Color(0.0f)),
      reliable_(sum_.size(), 0) {}

void AdjointCache::update(int entry) {
    const uint32_t n = count_[size_t(entry)];
    mean_[size_t(entry)] = n > 0 ? Color(sum_[size_t(entry)] / double(n)) : Color(0.0f);
    reliable_[size_t(entry)] = relativeError(entry) <= kMaxRelativeError ? 1 : 0;
}

void AdjointCache::add(int entry, const Color& value) {
    sum_[size_t(entry)] += DColor(value);
    const double m = (double(value.r) + double(value.g) + double(value.b)) / 3.0;
    sumSq_[size_t(entry)] += m * m;
    ++count_[size_t(entry)];
    update(entry);
}

float AdjointCache::relativeError(int entry) const {
    const double n = count_[size_t(entry)];
    const DColor& s = sum_[size_t(entry)];
    const double mean = (s.x + s.y + s.z) / (3.0 * n);
    if (exact_[size_t(entry)] && mean > 0.0) return 0.0f;
    if (n < 2 || !(mean > 0.0)) return kInf;
    const double var = std::max(0.0, (sumSq_[size_t(entry)] - n * mean * mean) / (n - 1.0));
    return float(std::sqrt(var / n) / mean);
}

void AdjointCache::set(int entry, const Color& value) {
    sum_[size_t(entry)] = DColor(value);
    const double m = (double(value.r) + double(value.g) + double(value.b)) / 3.0;
    sumSq_[size_t(entry)] = m * m;
    count_[size_t(entry)] = 1;
    exact_[size_t(entry)] = 1;
    update(entry);
}

int AdjointCache::reliableEntries() const {
    int n = 0;
    for (int e = 0; e < entries(); ++e) n += reliable(e) ? 1 : 0;
    return n;
}

}  // namespace ps
