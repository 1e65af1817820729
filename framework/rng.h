// PCG32 random numbers (O'Neill 2014) with streams derived from (seed, iteration, pixel):
// every sample's randomness is a function of where and when it is taken, never of which
// thread takes it, so images are bit-identical for any thread count.
#pragma once
#include <cstdint>
#include "vecmath.h"

// A branch the hot loop almost never takes (numbers are replayed only by a Metropolis sampler).
#if defined(__GNUC__) || defined(__clang__)
#define PS_UNLIKELY(x) __builtin_expect(!!(x), 0)
#else
#define PS_UNLIKELY(x) (x)
#endif

namespace ps {

// SplitMix64 finaliser: a bijective 64-bit mix, used to decorrelate seeds.
inline uint64_t mix64(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// Where an Rng's uniform() takes its numbers from instead of its own generator: a Metropolis
// sampler replays a vector of primary samples through an unchanged path tracer.
class UniformSource {
public:
    virtual float next() = 0;  // the next number in [0, 1)

protected:
    ~UniformSource() = default;
};

class Rng {
public:
    explicit Rng(uint64_t seed = 0, uint64_t stream = 0) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        nextU32();
        state_ += seed;
        nextU32();
    }
    uint32_t nextU32() {
        uint64_t old = state_;
        state_ = old * 6364136223846793005ull + inc_;
        uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
        uint32_t rot = static_cast<uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
    }
    // Uniform in [0, 1): 24 random bits, so the result is never 1. While replaying (replayFrom),
    // the source's next number instead.
    float uniform() {
        if (PS_UNLIKELY(source_ != nullptr)) return source_->next();
        return static_cast<float>(nextU32() >> 8) * 0x1p-24f;
    }
    Vec2 uniform2() {
        float a = uniform();
        return Vec2(a, uniform());
    }
    // Uniform in [0, 1) with 53 random bits.
    double uniformDouble() {
        uint64_t hi = nextU32(), lo = nextU32();
        return static_cast<double>(((hi << 32) | lo) >> 11) * 0x1p-53;
    }
    // From now on uniform() and uniform2() return source->next() (nullptr: the generator again).
    // Only those two: nextU32() and uniformDouble() always use the generator.
    void replayFrom(UniformSource* source) { source_ = source; }

private:
    uint64_t state_, inc_;
    UniformSource* source_ = nullptr;
};

// The generator for one task (a pixel, or a batch of light paths) in one iteration.
inline Rng taskRng(uint64_t seed, uint32_t iteration, uint32_t task) {
    return Rng(mix64(mix64(seed) ^ (static_cast<uint64_t>(iteration) << 32 | task)),
               mix64(seed + 0x632be59bd9b4e019ull) ^ task);
}

}  // namespace ps
