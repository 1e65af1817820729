// Lesson 10, graded: the weight window (Eq. 10.5, 10.6) and the expected number of continuations it
// gives (Eq. 10.7), against values computed by hand.
#include "lesson10.h"

using namespace lesson10;

namespace {
bool close(float got, double want) { return std::abs(double(got) - want) <= 1e-6 * std::abs(want); }
}  // namespace

TEST_CASE("weight window: centre I~ / Psi~, bounds 2 C / (1 + s) and s times that (Eq. 10.5, 10.6) [1 pt]") {
    struct Case {
        float I, psi, s;
        double centre, lower, upper;
    };
    for (const Case& c : {Case{2.0f, 0.5f, 5.0f, 4.0, 8.0 / 6.0, 40.0 / 6.0}, Case{0.3f, 0.1f, 3.0f, 3.0, 1.5, 4.5},
                          Case{1.0f, 4.0f, 5.0f, 0.25, 0.5 / 6.0, 2.5 / 6.0}, Case{0.0f, 2.0f, 5.0f, 0.0, 0.0, 0.0}}) {
        const ps::WeightWindow w = ps::weightWindow(c.I, c.psi, c.s);
        const bool centreOk = c.centre == 0.0 ? w.centre == 0.0f : close(w.centre, c.centre);
        CHECK_MESSAGE(centreOk, "weightWindow(I~ "
                                    << c.I << ", Psi~ " << c.psi << ", s " << c.s
                                    << "): expected the centre C_ww = I~ / Psi~ = " << c.centre << " (Eq. 10.5), got "
                                    << w.centre << (close(w.centre, c.psi) ? " (Psi~: the centre is I~ / Psi~)" : ""));
        const bool boundsOk = c.centre == 0.0 ? (w.lower == 0.0f && w.upper == 0.0f)
                                              : (close(w.lower, c.lower) && close(w.upper, c.upper));
        CHECK_MESSAGE(boundsOk, "weightWindow(I~ " << c.I << ", Psi~ " << c.psi << ", s " << c.s
                                                   << "): expected the bounds [2 C / (1 + s), s 2 C / (1 + s)] = ["
                                                   << c.lower << ", " << c.upper << "] (Eq. 10.6), got [" << w.lower
                                                   << ", " << w.upper << "]");
    }
    const ps::WeightWindow none = ps::weightWindow(1.0f, 0.0f);
    CHECK_MESSAGE((std::isinf(none.centre) && std::isinf(none.lower) && std::isinf(none.upper) && none.lower > 0),
                  "weightWindow(I~ 1, Psi~ 0): the cache says the path collects nothing: expected every bound "
                  "+infinity, got centre "
                      << none.centre << ", [" << none.lower << ", " << none.upper << "]");
    const ps::WeightWindow byDefault = ps::weightWindow(2.0f, 0.5f);
    CHECK_MESSAGE(close(byDefault.upper / byDefault.lower, 5.0),
                  "weightWindow without a ratio: expected s = kWindowRatio = 5, got upper / lower = "
                      << byDefault.upper / byDefault.lower);
}

TEST_CASE("weight window: roulette below it, splitting above it, nothing inside, clamped (Eq. 10.7) [1 pt]") {
    ps::WeightWindow w;  // I~ = 2, Psi~ = 0.5, s = 5
    w.centre = 4.0f;
    w.lower = 4.0f / 3.0f;
    w.upper = 20.0f / 3.0f;
    struct Case {
        float nu;
        double q;
        const char* why;
    };
    for (const Case& c :
         {Case{1.0f, 0.75, "below the window: q = nu / delta-"}, Case{4.0f, 1.0, "inside the window: q = 1"},
          Case{4.0f / 3.0f, 1.0, "on the lower bound (inside): q = 1"},
          Case{20.0f / 3.0f, 1.0, "on the upper bound (inside): q = 1"},
          Case{10.0f, 1.5, "above the window: q = nu / delta+"}, Case{40.0f, 6.0, "above the window: q = nu / delta+"},
          Case{0.01f, ps::kMinContinuations, "below: nu / delta- = 0.0075, clamped to kMinContinuations"},
          Case{100.0f, ps::kMaxContinuations, "above: nu / delta+ = 15, clamped to kMaxContinuations"}}) {
        const float q = ps::expectedContinuations(c.nu, w);
        CHECK_MESSAGE(close(q, c.q), "expectedContinuations(nu " << c.nu << ", window [" << w.lower << ", " << w.upper
                                                                 << "]): expected q = " << c.q << " (" << c.why
                                                                 << ", Eq. 10.7), got " << q);
    }
    const float none = ps::expectedContinuations(1.0f, ps::weightWindow(1.0f, 0.0f));
    CHECK_MESSAGE(close(none, ps::kMinContinuations),
                  "a path the cache says collects nothing (Psi~ = 0): expected q = kMinContinuations = "
                      << ps::kMinContinuations << ", got " << none);
    const float dark = ps::expectedContinuations(0.5f, ps::weightWindow(0.0f, 2.0f));
    CHECK_MESSAGE(close(dark, ps::kMaxContinuations),
                  "a path that collects something (Psi~ = 2) in a pixel estimated black (I~ = 0): expected q = "
                  "kMaxContinuations = "
                      << ps::kMaxContinuations << ", got " << dark);
}
