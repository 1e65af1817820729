// Lesson 13, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 13.E1).
// The student's iteration against the weight of the merge (Eq. 13.4 for the four techniques of a
// path of length 2) solved for 1/2 numerically here: bisection on the logarithm of i.
#include <doctest/doctest.h>
#include <cmath>
#include <limits>
#include "13-vcm/exercises.h"

namespace {

// The merge's weight at iteration i (Eq. 13.4 with eta_i = eta1 i^(alpha - 1)).
double mergeWeight(const double p[3], double pL1, double eta1, double alpha, double b, double i) {
    const double merge = std::pow(eta1 * std::pow(i, alpha - 1.0) * pL1 * p[1], b);
    return merge / (merge + std::pow(p[0], b) + std::pow(p[1], b) + std::pow(p[2], b));
}

}  // namespace

TEST_CASE("exercise: the iteration at which merging gives up half its weight (Eq. 13.E1) [1 pt]") {
    struct Case {
        double pdf[3], pL1, eta1, alpha, b;
    };
    const Case cases[] = {
        {{1e-6, 2e-6, 3e-7}, 4e-6, 3e5, 0.75, 1.0},     {{1e-6, 2e-6, 3e-7}, 4e-6, 3e5, 0.75, 2.0},
        {{0.0, 5e-3, 1e-3}, 1e-2, 1e4, 2.0 / 3.0, 2.0}, {{1.0, 1.0, 1.0}, 1.0, 0.5, 0.75, 2.0},  // below 1/2 at once
        {{1.0, 2.0, 0.5}, 3.0, 10.0, 1.0, 1.0},  // a fixed radius: never
    };
    for (const Case& c : cases) {
        const double got = ps::halfMergeIteration(c.pdf, c.pL1, c.eta1, c.alpha, c.b);
        double expected;
        if (mergeWeight(c.pdf, c.pL1, c.eta1, c.alpha, c.b, 1.0) <= 0.5) expected = 1.0;
        else if (c.alpha >= 1.0) expected = std::numeric_limits<double>::infinity();
        else {
            double lo = 0.0, hi = 200.0;  // log i
            for (int k = 0; k < 200; ++k) {
                const double mid = 0.5 * (lo + hi);
                (mergeWeight(c.pdf, c.pL1, c.eta1, c.alpha, c.b, std::exp(mid)) > 0.5 ? lo : hi) = mid;
            }
            expected = std::exp(0.5 * (lo + hi));
        }
        const bool ok =
            std::isinf(expected) ? std::isinf(got) && got > 0.0 : std::abs(got - expected) <= 1e-6 * expected;
        CHECK_MESSAGE(ok, "halfMergeIteration(pdfs " << c.pdf[0] << ", " << c.pdf[1] << ", " << c.pdf[2]
                                                     << ", p_L(x_1) " << c.pL1 << ", eta_1 " << c.eta1 << ", alpha "
                                                     << c.alpha << ", b " << c.b << "): expected " << expected
                                                     << ", got " << got);
    }
}
