// Lesson 9, graded: the one-dimensional Metropolis sampler (Eq. 9.1-9.3): the mutations and
// their densities, detailed balance, one step of the chain replayed, and the states of many
// independent chains against f / b.
#include "lesson09.h"

using namespace lesson09;

TEST_CASE("1D: the mutations propose what they say, with their transition densities (Eq. 9.1) [1 pt]") {
    for (const double x : {0.0, 0.03, 0.3, 0.5, 0.81, 0.999}) {
        for (const double u : {0.0, 0.2, 0.5, 0.75, 0.999999}) {
            const ps::Proposal p = ps::mutateIndependent(x, u);
            CHECK_MESSAGE((p.y == u && p.Txy == 1.0 && p.Tyx == 1.0),
                          "mutateIndependent(x " << x << ", u " << u << "): expected y = u = " << u
                                                 << ", Txy = Tyx = 1, got y " << num(p.y) << ", Txy " << num(p.Txy)
                                                 << ", Tyx " << num(p.Tyx));
            for (const double r : {0.1, 0.25}) {
                const ps::Proposal q = ps::mutateLocal(x, u, r);
                const double y = windowLo(x, r) + u * windowLength(x, r);
                CHECK_MESSAGE(std::abs(q.y - y) <= 1e-12,
                              "mutateLocal(x " << x << ", u " << u << ", r " << r
                                               << "): expected y = lo + u (hi - lo) = " << num(y) << " in the window ["
                                               << windowLo(x, r) << ", " << windowHi(x, r) << "], got " << num(q.y)
                                               << (q.y == 0.0 || q.y == 1.0 ? " (clamped to the end?)" : ""));
                const double Txy = 1.0 / windowLength(x, r), Tyx = 1.0 / windowLength(y, r);
                CHECK_MESSAGE((std::abs(q.Txy - Txy) <= 1e-9 * Txy && std::abs(q.Tyx - Tyx) <= 1e-9 * Tyx),
                              "mutateLocal(x "
                                  << x << ", u " << u << ", r " << r << ") -> y " << num(y)
                                  << ": expected T(x -> y) = 1 / |window(x)| = " << num(Txy)
                                  << " and T(y -> x) = 1 / |window(y)| = " << num(Tyx) << ", got " << num(q.Txy)
                                  << " and " << num(q.Tyx)
                                  << (q.Txy == q.Tyx && Txy != Tyx ? " (the cut window makes them differ)" : ""));
            }
        }
    }
    const ps::Mutations m{0.3, 0.1};
    for (const double uSelect : {0.0, 0.29, 0.31, 0.9}) {
        const ps::Proposal p = ps::mutate(0.05, uSelect, 0.6, m);
        const ps::Proposal want = uSelect < m.pLarge ? ps::Proposal{0.6, 1.0, 1.0} : ps::mutateLocal(0.05, 0.6, m.r);
        CHECK_MESSAGE(
            (std::abs(p.y - want.y) < 1e-12 && std::abs(p.Txy - want.Txy) < 1e-9 && std::abs(p.Tyx - want.Tyx) < 1e-9),
            "mutate(x 0.05, uSelect " << uSelect << ", u 0.6, pLarge 0.3, r 0.1): expected the "
                                      << (uSelect < m.pLarge ? "independent" : "local") << " mutation's y "
                                      << num(want.y) << ", got " << num(p.y));
    }
}

TEST_CASE(
    "1D: detailed balance holds exactly for the local mutation cut at the ends of the interval (Eq. 9.2, 9.3) [2 pts]") {
    // f(x) T(x -> y) a(x -> y) = f(y) T(y -> x) a(y -> x) for every pair the local mutation
    // connects, with the true densities of the cut window (the test's own): near 0 and 1 they
    // differ, and an acceptance without them breaks the balance there.
    const double r = 0.25;
    struct Target {
        const char* name;
        double (*f)(double);
    };
    for (const Target t : {Target{"(x - 1/2)^2", lectureTarget}, Target{"exp(3x)", expTarget}}) {
        int broken = 0;
        std::string first;
        for (int i = 0; i <= 40; ++i)
            for (int j = 0; j <= 40; ++j) {
                const double x = 0.01 + 0.98 * i / 40.0, y = 0.01 + 0.98 * j / 40.0;
                if (i == j || std::abs(x - y) > r || t.f(x) * t.f(y) == 0.0) continue;
                const double Txy = 1.0 / windowLength(x, r), Tyx = 1.0 / windowLength(y, r);
                const double axy = ps::acceptance(t.f(x), t.f(y), ps::Proposal{y, Txy, Tyx});
                const double ayx = ps::acceptance(t.f(y), t.f(x), ps::Proposal{x, Tyx, Txy});
                const double lhs = t.f(x) * Txy * axy, rhs = t.f(y) * Tyx * ayx;
                const bool ok = std::abs(lhs - rhs) <= 1e-12 * std::max(lhs, rhs) && axy >= 0.0 && axy <= 1.0 &&
                                ayx >= 0.0 && ayx <= 1.0 && lhs > 0.0 && (axy == 1.0 || ayx == 1.0);
                if (!ok && broken++ == 0)
                    first = "x " + num(x) + ", y " + num(y) + ": T(x->y) " + num(Txy) + ", T(y->x) " + num(Tyx) +
                            ", a(x->y) " + num(axy) + ", a(y->x) " + num(ayx) + ", f(x) T a = " + num(lhs) +
                            ", f(y) T a = " + num(rhs);
            }
        CHECK_MESSAGE(broken == 0,
                      "f = " << t.name
                             << ", local mutation of radius 0.25: expected f(x) T(x->y) a(x->y) = f(y) "
                                "T(y->x) a(y->x) (and a in [0, 1], 1 one way), broken for "
                             << broken << " pairs, the first: " << first
                             << "\n  (a = min(1, f(y) T(y->x) / (f(x) T(x->y))): are the transition densities in it?)");
    }
}

TEST_CASE("1D: one step of the chain draws three numbers, proposes, and accepts with probability a [1 pt]") {
    // Replayed with a copy of the step's generator: uSelect, u, the acceptance number.
    const ps::Mutations m{0.3, 0.2};
    int moved = 0, stayed = 0;
    for (int i = 0; i < 400; ++i) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(901), 0, uint32_t(i));
        ps::Rng replay = rng;
        const double x = 0.02 + 0.96 * (i % 97) / 96.0;
        const ps::Step s = ps::metropolisStep(lectureTarget, x, m, rng);
        const double uSelect = replay.uniformDouble(), u = replay.uniformDouble(), uAccept = replay.uniformDouble();
        const ps::Proposal p = uSelect < m.pLarge ? ps::Proposal{u, 1.0, 1.0}
                                                  : ps::Proposal{windowLo(x, m.r) + u * windowLength(x, m.r),
                                                                 1.0 / windowLength(x, m.r), 0.0};
        const double Tyx = uSelect < m.pLarge ? 1.0 : 1.0 / windowLength(p.y, m.r);
        const double a = std::min(1.0, lectureTarget(p.y) * Tyx / (lectureTarget(x) * p.Txy));
        const double next = uAccept < a ? p.y : x;
        (next == x ? stayed : moved)++;
        CHECK_MESSAGE(
            (std::abs(s.p.y - p.y) < 1e-12 && std::abs(s.a - a) < 1e-9 && s.next == (uAccept < a ? s.p.y : x)),
            "metropolisStep from x " << num(x) << " (uSelect " << num(uSelect) << ", u " << num(u)
                                     << ", acceptance number " << num(uAccept) << "): expected proposal " << num(p.y)
                                     << ", a " << num(a) << ", next state " << num(next) << ", got proposal "
                                     << num(s.p.y) << ", a " << num(s.a) << ", next state " << num(s.next));
        if (std::abs(s.next - next) > 1e-12) break;
    }
    CHECK_MESSAGE((moved > 50 && stayed > 50),
                  "the replayed steps should both move and stay: " << moved << " moved, " << stayed << " stayed");
}

namespace {

// The final states of kChains independent chains of kSteps steps each, every chain from its own
// generator and from a start x0 away from where f is largest, binned into kBins cells, against
// f / b (chi-square). The independent mutation alone forgets the start geometrically: from any x
// it moves to dy with probability at least pLarge min(1, f(y) / f(x)) dy >= pLarge (b / max f)
// f(y) / b dy, so after kSteps steps the final state's distribution is within
// (1 - pLarge b / max f)^kSteps of f / b: 7e-10 for (x - 1/2)^2, 2e-9 for exp(3x), far below
// what the test can resolve.
void checkChains(const char* name, double (*f)(double), double b, double fMax, double x0, uint64_t seed) {
    const ps::Mutations m{0.3, 0.25};
    constexpr int kChains = 20000, kSteps = 200, kBins = 25;
    std::vector<double> observed(kBins, 0.0), expected(kBins, 0.0);
    for (int c = 0; c < kChains; ++c) {
        ps::Rng rng = ps::taskRng(ps::testseed::seed(seed), 0, uint32_t(c));
        double x = x0;
        for (int k = 0; k < kSteps; ++k) x = ps::metropolisStep(f, x, m, rng).next;
        if (x >= 0.0 && x <= 1.0) observed[size_t(std::min(kBins - 1, int(x * kBins)))] += 1.0;
    }
    for (int i = 0; i < kBins; ++i) {  // Simpson's rule on each cell, 64 intervals
        const double lo = double(i) / kBins, h = 1.0 / (kBins * 64.0);
        double s = 0.0;
        for (int k = 0; k <= 64; ++k) s += (k == 0 || k == 64 ? 1.0 : (k % 2 ? 4.0 : 2.0)) * f(lo + k * h);
        expected[size_t(i)] = kChains * s * h / 3.0 / b;
    }
    const ps::stats::ChiSquareResult r = ps::stats::chiSquare(observed, expected, alpha());
    CHECK_MESSAGE(r.passed, "f = " << name << ": the final states of " << kChains << " independent chains of " << kSteps
                                   << " steps (mixture pLarge 0.3, local radius 0.25, start x0 = " << x0 << ", max f "
                                   << fMax << ") should be distributed as f / b:\n  " << r.report
                                   << "\n  (too few near 0 and 1: transition densities left out of the acceptance, or "
                                      "the local window clamped instead of cut?)");
}

}  // namespace

TEST_CASE("1D: the final states of independent chains are distributed as f / b (chi-square) [2 pts]") {
    checkChains("(x - 1/2)^2", lectureTarget, 1.0 / 12.0, 0.25, 0.45, 911);
    checkChains("exp(3x)", expTarget, expTargetIntegral(), std::exp(3.0), 0.05, 912);
}
