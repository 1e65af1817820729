// Lesson 10, graded: survival and splitting (Eq. 10.3, 10.4): the number of continuations n over a
// regular grid of the uniform number u (so E[n] is exact up to the grid's spacing, no chance
// involved) and the weight beta / q of every continuation.
#include "lesson10.h"

using namespace lesson10;

namespace {

// n and the weight for q and beta, with u replayed: u_i = (i + 1/2) / N for i = 0 .. N - 1.
void checkQ(float q) {
    constexpr int N = 10000;
    const Color beta(0.8f, 0.5f, 0.25f);
    const int lo = int(std::floor(q));
    const float fraction = q - float(lo);
    double sumN = 0.0;
    int wrongN = 0, wrongWeight = 0;
    std::string firstWrong;
    size_t drawn = 0;
    for (int i = 0; i < N; ++i) {
        Replay replay;
        replay.values = {(float(i) + 0.5f) / float(N)};
        ps::Rng rng;
        rng.replayFrom(&replay);
        const ps::Continuations c = ps::continuations(beta, q, rng);
        drawn += replay.read;
        sumN += c.n;
        const int want = replay.values[0] < fraction ? lo + 1 : lo;
        if (c.n != want && wrongN++ == 0)
            firstWrong = "u = " + num(replay.values[0]) + ": expected n = " + std::to_string(want) + ", got " +
                         std::to_string(c.n);
        if (!(c.beta.r == beta.r / q && c.beta.g == beta.g / q && c.beta.b == beta.b / q)) ++wrongWeight;
        if (i == 0)
            CHECK_MESSAGE((c.beta.r == beta.r / q && c.beta.g == beta.g / q && c.beta.b == beta.b / q),
                          "continuations(beta " << str(beta) << ", q " << q
                                                << "): every continuation must carry beta / q = " << str(beta / q)
                                                << " (Eq. 10.3), got " << str(c.beta)
                                                << (c.beta == beta ? " (beta itself: not divided by q)" : ""));
    }
    const double mean = sumN / N;
    CHECK_MESSAGE(
        std::abs(mean - double(q)) <= 1.0 / N,
        "continuations(q " << q << "): over u on a regular grid of " << N
                           << " points the mean of n must be q (Eq. 10.4: n = floor(q) + 1 with probability "
                              "q - floor(q)), got "
                           << num(mean) << (std::abs(mean - lo) <= 1.0 / N ? " = floor(q): the fraction is lost" : "")
                           << (q < 1.0f && mean == 1.0 ? " (q < 1 must be Russian roulette, not one path always)"
                                                       : ""));
    CHECK_MESSAGE(wrongN == 0, "continuations(q " << q << "): n must be floor(q) + 1 exactly when u < q - floor(q); "
                                                  << wrongN << " of " << N
                                                  << " draws wrong, the first: " << firstWrong);
    CHECK_MESSAGE(wrongWeight == 0,
                  "continuations(q " << q << "): " << wrongWeight << " of " << N << " draws did not carry beta / q");
    const bool whole = fraction == 0.0f;
    CHECK_MESSAGE(
        drawn == (whole ? 0u : size_t(N)),
        "continuations(q " << q << "): expected "
                           << (whole ? "no uniform number (q is a whole number)" : "one uniform number per call")
                           << ", got " << drawn << " numbers in " << N << " calls");
}

}  // namespace

TEST_CASE(
    "survival and splitting: E[n] = q and every continuation carries beta / q, for q < 1 (Eq. 10.3, 10.4) [1 pt]") {
    for (const float q : {0.05f, 0.3f, 0.7f}) checkQ(q);
}

TEST_CASE(
    "survival and splitting: E[n] = q and every continuation carries beta / q, for q >= 1 (Eq. 10.3, 10.4) [1 pt]") {
    for (const float q : {1.0f, 1.25f, 2.0f, 2.7f, 7.75f}) checkQ(q);
}
