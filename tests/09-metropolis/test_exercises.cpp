// Lesson 9, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 9.E1).
// The student's closed form against the flux of Eq. 9.3 across x = 1/2 integrated numerically
// (lesson09.h: midpoint rule in both variables, 2000 x 2000 cells per direction).
#include <cmath>
#include "09-metropolis/exercises.h"
#include "lesson09.h"

TEST_CASE("exercise: the rate at which local mutations cross x = 1/2 (Eq. 9.E1) [1 pt]") {
    for (const double r : {0.01, 0.05, 0.1, 0.2, 0.25}) {
        const double expected = lesson09::crossingRateByQuadrature(r), got = ps::crossingRate(r);
        CHECK_MESSAGE(std::abs(got - expected) <= 1e-4 * expected,
                      "crossingRate(r " << r << "): expected " << expected
                                        << " (both directions of the flux of Eq. 9.3 across 1/2), got " << got);
    }
}
