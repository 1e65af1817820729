// Lesson 5, graded: the pen-and-paper exercise (README, "Exercise (pen and paper)", Eq. 5.E1).
// The student's radiance scale across a refraction against an independent evaluation: the
// refracted flux equals the incident flux (no Fresnel), L_i cos(theta_i) d(omega_i) =
// L_t cos(theta_t) d(omega_t), with d(omega) = sin(theta) d(theta) d(phi) on both sides (phi is
// kept) and d(theta_t)/d(theta_i) from Snell's law by a central finite difference.
#include <doctest/doctest.h>
#include <cmath>
#include <initializer_list>
#include "05-light-tracing/exercises.h"

TEST_CASE("exercise: how radiance scales across a refraction, from Snell's law (Eq. 5.E1) [1 pt]") {
    const double etas[][2] = {{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.33}, {1.33, 1.0}, {1.0, 2.4}, {1.5, 1.5}};
    for (const auto& e : etas) {
        const double etaFrom = e[0], etaTo = e[1];
        auto thetaT = [&](double ti) { return std::asin(etaFrom / etaTo * std::sin(ti)); };
        for (double ti : {0.1, 0.4, 0.6}) {  // below the critical angle of every pair (0.73 for 1.5 -> 1)
            const double h = 1e-6, tt = thetaT(ti);
            const double dtt = (thetaT(ti + h) - thetaT(ti - h)) / (2.0 * h);
            const double expected = std::cos(ti) * std::sin(ti) / (std::cos(tt) * std::sin(tt) * dtt);
            const double got = ps::refractedRadianceScale(etaFrom, etaTo);
            CHECK_MESSAGE(std::abs(got / expected - 1.0) < 1e-6,
                          "refractedRadianceScale(from eta "
                              << etaFrom << " to eta " << etaTo << "), at theta_i " << ti
                              << ": expected L_t / L_i = " << expected << " (flux conserved through Snell's beam), got "
                              << got << " (ratio " << got / expected
                              << (std::abs(got * expected - 1.0) < 1e-6 ? ": upside down" : "") << ")");
        }
    }
}
