// Lesson 1's low-discrepancy points: the radical inverse, the Halton sequence, and randomised
// quasi-Monte Carlo (a Cranley-Patterson rotation of Halton points) over the unit square.
// Implemented in solutions/01-monte-carlo/lowdiscrepancy.cpp (reference) or
// assignments/01-monte-carlo/lowdiscrepancy.cpp (yours); lessons/01-monte-carlo/README.md,
// section 1.8, derives every formula (Eq. 1.15-1.20). Everything here is deterministic except the
// rotation's shifts, which come from the Rng passed in: same seed, same estimate.
#pragma once
#include <cstdint>
#include "01-monte-carlo/estimators.h"

namespace ps {

// The bases of the Halton sequence's coordinates, dimension 0 first: the first eight primes,
// pairwise coprime (Eq. 1.19 says why they must be).
constexpr unsigned kHaltonBases[] = {2, 3, 5, 7, 11, 13, 17, 19};
constexpr int kHaltonDimensions = 8;

// The radical inverse Phi_b(i) of Eq. 1.15: index i's base-b digits mirrored about the radix
// point. Any 64-bit index, base 2 <= b <= 65536; the result lies in [0, 1) for every index,
// the largest included.
double radicalInverse(uint64_t index, unsigned base);

// Coordinate `dimension` (0 <= dimension < kHaltonDimensions) of the Halton point with index i
// (Eq. 1.19), in [0, 1). Point 0 is the origin.
double halton(uint64_t index, int dimension);

// The Cranley-Patterson rotation of one coordinate (Eq. 1.20): x in [0, 1) moved by shift in
// [0, 1) around the unit circle; the result lies in [0, 1).
double cranleyPatterson(double x, double shift);

// Randomised quasi-Monte Carlo (Eq. 1.20): the integral of f over the unit square from
// `replicates` >= 2 independent rotations of the same n >= 1 Halton points, indices 0..n-1
// (dimensions 0 and 1). Each replicate draws its own shift from rng; the value is the mean of
// the replicates' averages, and the variance is that mean's, estimated from the replicates'
// spread (Eq. 1.3 with the replicates as the samples). n * replicates evaluations of f.
Estimate estimateHalton2D(const Function2D& f, int n, int replicates, Rng& rng);

}  // namespace ps
