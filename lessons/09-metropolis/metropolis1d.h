// Lesson 9's one-dimensional Metropolis sampler: a chain on [0, 1] whose states are distributed
// as f / b (b = the integral of f), for any f >= 0 it can evaluate, without knowing b. Two
// mutations propose the next state (independent and local), a mixture picks one of them, the
// acceptance probability with the transition densities (Eq. 9.2) keeps the chain in detailed
// balance (Eq. 9.3), and the chain estimates integrals of g f with the expected-values
// estimator (Eq. 9.5) and a normalisation b estimated separately (Eq. 9.6). Implemented in
// solutions/09-metropolis/*.cpp (reference) or assignments/09-metropolis/*.cpp (yours);
// lessons/09-metropolis/README.md derives every formula (Eq. 9.1-9.6).
#pragma once
#include <functional>
#include "rng.h"

namespace ps {

// A target function on [0, 1], f(x) >= 0 (the lesson's example: (x - 1/2)^2).
using Function1D = std::function<double(double)>;

// A proposed move x -> y with both transition densities (Eq. 9.1): Txy = T(x -> y), the density
// with which the mutation proposes y from x, and Tyx = T(y -> x), the density with which the
// SAME mutation would propose x from y.
struct Proposal {
    double y = 0.0;
    double Txy = 1.0, Tyx = 1.0;
};

// Independent mutation: y = u, uniform on [0, 1] whatever x is (T = 1 both ways).
Proposal mutateIndependent(double x, double u);

// Local mutation of radius r (0 < r <= 1/2): y uniform in the window [max(0, x - r), min(1, x + r)],
// y = lo + u (hi - lo). The window is cut at the ends of [0, 1], so it is shorter near them and
// the mutation is NOT symmetric there: T(x -> y) = 1 / (length of x's window) (Eq. 9.1).
Proposal mutateLocal(double x, double u, double r);

// The mixture: with probability pLarge (uSelect < pLarge) the independent mutation, else the
// local one, each with its own densities; u is the chosen mutation's number.
struct Mutations {
    double pLarge = 0.5;  // probability of the independent mutation
    double r = 0.1;       // radius of the local mutation
};
Proposal mutate(double x, double uSelect, double u, const Mutations& m);

// The Metropolis-Hastings acceptance probability of the move (Eq. 9.2):
// a = min(1, f(y) T(y -> x) / (f(x) T(x -> y))), for fx = f(x) > 0.
double acceptance(double fx, double fy, const Proposal& p);

// One step of the chain from x (f(x) > 0): draws uSelect, u and the acceptance number, in
// that order, each rng.uniformDouble(); proposes p = mutate(x, uSelect, u, m), accepts with
// probability a (the number < a) and moves to p.y, else stays at x.
struct Step {
    double next = 0.0;  // the state after the step: p.y if accepted, else x
    Proposal p;         // the proposal
    double a = 0.0;     // its acceptance probability
};
Step metropolisStep(const Function1D& f, double x, const Mutations& m, Rng& rng);

// b = integral of f over [0, 1], estimated separately by n uniform samples (Eq. 9.6):
// the mean of f(rng.uniformDouble()).
double estimateNormalization(const Function1D& f, int n, Rng& rng);

// The Metropolis estimate of the integral of g f over [0, 1] (Eq. 9.6): the chain
// x_0 = x0 (f(x0) > 0), x_1, ..., x_n of n metropolisStep's with rng, and b times the chain's
// average of g, in two ways from the same chain: plain, the mean of g over the states
// x_1 .. x_n (Eq. 9.4), and with expected values, the mean over the steps of
// (1 - a) g(x) + a g(y) (Eq. 9.5).
struct Quadrature {
    double plain = 0.0, expected = 0.0;
};
Quadrature metropolisQuadrature(const Function1D& f, const Function1D& g, double b, double x0, int n,
                                const Mutations& m, Rng& rng);

}  // namespace ps
