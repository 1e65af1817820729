// Lesson 9, graded: what the one-dimensional chain estimates (Eq. 9.3-9.6): local mutations alone
// cross x = 1/2 as rarely as theory says, and the expected-values estimator has the plain chain's
// mean and a lower variance.
#include "lesson09.h"

using namespace lesson09;

TEST_CASE(
    "1D: local mutations alone stay stuck in one half: they cross x = 1/2 as rarely as Eq. 9.E1 says (t-test) [2 pts]") {
    // f(x) = (x - 1/2)^2 is 0 at 1/2: a chain of local mutations of radius r must climb through
    // the valley to reach the other half. Started in the stationary distribution (the inverse
    // CDF of f / b), each step crosses 1/2 with probability exactly the flux of Eq. 9.3 across
    // it (README, Eq. 9.E1; integrated numerically here, lesson09.h): with r = 0.2 one crossing
    // per 500 steps. t-test on the crossings of kChains independent chains, power: standard error
    // at most 5 % of the rate.
    constexpr int kChains = 4000, kSteps = 500;
    constexpr double r = 0.2;
    const double rate = crossingRateByQuadrature(r);
    const ps::Mutations local{0.0, r};
    ps::stats::Welford crossings;
    int neverCrossed = 0;
    for (int c = 0; c < kChains; ++c) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(921), 0, uint32_t(c));
        double x = sampleLectureTarget(rng.uniformDouble());
        int n = 0;
        for (int k = 0; k < kSteps; ++k) {
            const double y = ps::metropolisStep(lectureTarget, x, local, rng).next;
            n += (x < 0.5) != (y < 0.5);
            x = y;
        }
        crossings.add(double(n) / kSteps);
        neverCrossed += n == 0;
    }
    const ps::stats::TTestResult t = ps::stats::tTest(crossings, rate, alpha(), 0.05);
    MESSAGE(neverCrossed << " of " << kChains << " chains never left the half they started in within " << kSteps
                         << " steps");
    CHECK_MESSAGE(t.passed, "local mutations alone (r = 0.2), "
                                << kChains << " chains of " << kSteps << " steps started in f / b: expected " << rate
                                << " crossings of x = 1/2 per step (the flux of Eq. 9.3), got " << t.mean << " +- "
                                << t.stdError << "\n  " << t.report
                                << "\n  (0: the chain never moves; far more: a local "
                                   "mutation that jumps, or an acceptance above "
                                   "f(y) / f(x)?)");
}

TEST_CASE(
    "1D: expected values: the plain chain's mean and a lower variance, with b estimated separately (Eq. 9.4-9.6) [2 pts]") {
    // The integral of g f with g(x) = x^2 and f(x) = (x - 1/2)^2 is exactly 1/30 (b = 1/12,
    // E[g] under f / b = 2/5). kChains independent chains, each started after kBurnIn steps from
    // x = 0.05 (the start is forgotten to within 7e-10, see test_chain1d.cpp), each giving both
    // estimates from the same kSteps steps.
    //   Means: b estimated by estimateNormalization with 1000 uniform samples, t-tests against
    //   1/30 (power: standard error at most 1 % of it; measured 0.7 %).
    //   Variance: the same chains with the exact b, so that only the chain's own noise counts; the
    //   Pitman-Morgan test of equal variances of the paired estimates (correlation of their sum
    //   and difference), one-sided: the expected-values estimate must have the lower variance
    //   at level alpha'. Measured: variance ratio 0.93, t = 22 (the test's critical t is below 4).
    const ps::Mutations m{0.3, 0.25};
    constexpr int kChains = 2000, kSteps = 100, kBurnIn = 200;
    const double exact = 1.0 / 30.0;
    const auto g = [](double x) { return x * x; };
    ps::stats::Welford plain, expected, plainB, expectedB;
    double sumPE = 0.0;
    for (int c = 0; c < kChains; ++c) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(931), 0, uint32_t(c));
        double x = 0.05;
        for (int k = 0; k < kBurnIn; ++k) x = ps::metropolisStep(lectureTarget, x, m, rng).next;
        ps::Rng rngB = rng;
        ps::Rng rngNorm = ps::taskRng(ps::testseed::seed(932), 0, uint32_t(c));
        const double b = ps::estimateNormalization(lectureTarget, 1000, rngNorm);
        const ps::Quadrature q = ps::metropolisQuadrature(lectureTarget, g, b, x, kSteps, m, rng);
        plain.add(q.plain);
        expected.add(q.expected);
        const ps::Quadrature e = ps::metropolisQuadrature(lectureTarget, g, 1.0 / 12.0, x, kSteps, m, rngB);
        plainB.add(e.plain);
        expectedB.add(e.expected);
        sumPE += e.plain * e.expected;
    }
    const ps::stats::TTestResult tp = ps::stats::tTest(plain, exact, alpha(), 0.01);
    const ps::stats::TTestResult te = ps::stats::tTest(expected, exact, alpha(), 0.01);
    CHECK_MESSAGE(tp.passed,
                  "plain chain estimate of the integral of x^2 (x - 1/2)^2 (Eq. 9.4 with b from Eq. 9.6): "
                  "expected 1/30 = "
                      << exact << ", got " << tp.mean << " +- " << tp.stdError << "\n  " << tp.report
                      << "\n  (b times the mean of g over the states after each step; b = the mean of f "
                         "over uniform samples)");
    CHECK_MESSAGE(te.passed, "expected-values estimate (Eq. 9.5): expected 1/30 = "
                                 << exact << ", got " << te.mean << " +- " << te.stdError << "\n  " << te.report
                                 << "\n  (weights: 1 - a on the current state, a on the proposal)");
    // Pitman-Morgan: Var P - Var E = Cov(P + E, P - E).
    const double n = double(kChains);
    const double cov = (sumPE - n * plainB.mean * expectedB.mean) / (n - 1.0);
    const double vp = plainB.variance(), ve = expectedB.variance();
    const double varS = vp + ve + 2.0 * cov, varD = vp + ve - 2.0 * cov;
    const double rho = varS > 0.0 && varD > 0.0 ? (vp - ve) / std::sqrt(varS * varD) : 0.0;
    const double t = rho * std::sqrt((n - 2.0) / std::max(1e-300, 1.0 - rho * rho));
    const double p = t > 0.0 ? 0.5 * ps::stats::studentTwoSided(t, n - 2.0) : 1.0;
    CHECK_MESSAGE(p < alpha(), "expected values should lower the variance of the chain's estimate: variance plain "
                                   << vp << ", expected values " << ve << " (ratio " << ve / vp
                                   << "), Pitman-Morgan t = " << t << ", one-sided p = " << p << ", alpha " << alpha()
                                   << "\n  (both estimates the same, or the proposal's a not used as its weight?)");
}
