// Lesson 13, graded (exact): the radius of each iteration (Eq. 13.12) against its definition
// evaluated here (r_1 times a power of i, checked through its logarithmic slope and its first
// values), and the merging factor eta (Eq. 13.5) against n_VM pi r^2.
#include <cmath>
#include "lesson13.h"

using namespace lesson13;

TEST_CASE("the radius of iteration i (Eq. 13.12) and the merging factor eta (Eq. 13.5) [1 pt]") {
    for (const double alpha : {0.75, 2.0 / 3.0, 0.5, 1.0}) {
        const double r1 = 0.37;
        for (const int i : {1, 2, 3, 10, 1000, 1000000}) {
            const double expected = r1 * std::exp(0.5 * (alpha - 1.0) * std::log(double(i)));
            const double got = ps::vcmRadius(r1, i, alpha);
            // The exponent the student's radius falls with between i = 10 and i = 1000.
            const double slope =
                std::log(ps::vcmRadius(r1, 1000, alpha) / ps::vcmRadius(r1, 10, alpha)) / std::log(100.0);
            std::string hint;
            if (std::abs(slope - (alpha - 1.0)) < 1e-6 && alpha != 1.0)
                hint = " (r falls like i^(alpha - 1): that is r^2's exponent, Eq. 13.12)";
            else if (std::abs(slope - 0.5 * (1.0 - alpha)) < 1e-6 && alpha != 1.0)
                hint = " (the radius grows: the sign of the exponent?)";
            else if (std::abs(ps::vcmRadius(r1, 1, alpha) - r1) > 1e-12)
                hint = " (iteration 1 must have r_1: iterations count from 1)";
            CHECK_MESSAGE(std::abs(got - expected) <= 1e-12 * expected,
                          "vcmRadius(r1 = " << num(r1) << ", i = " << i << ", alpha = " << num(alpha) << "): expected "
                                            << num(expected, 12) << ", got " << num(got, 12) << "; r falls like i^"
                                            << num(slope, 6) << hint);
        }
    }
    for (const double r : {1e-3, 0.5, 20.0})
        for (const int n : {1, 256, 262144}) {
            const double expected = double(n) * 3.14159265358979323846 * r * r;
            const double got = ps::mergeFactor(r, n);
            std::string hint;
            if (std::abs(got - 3.14159265358979323846 * r * r) <= 1e-6 * got && n > 1)
                hint = " (the number of light paths, n_VM, is missing)";
            else if (std::abs(got - double(n) * r * r) <= 1e-6 * got) hint = " (pi is missing)";
            CHECK_MESSAGE(std::abs(got - expected) <= 1e-6 * expected,
                          "mergeFactor(r = " << num(r) << ", light paths " << n << "): expected " << num(expected, 9)
                                             << ", got " << num(got, 9) << hint);
        }
}
