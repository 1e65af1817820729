// Lesson 2's multiple importance sampling weights (Veach 1997, ch. 9): several sampling
// techniques estimate the same integral; each sample is weighted by how likely every technique
// was to produce it. Implemented in solutions/02-direct-mis/mis.cpp (reference) or
// assignments/02-direct-mis/mis.cpp (yours); lessons/02-direct-mis/README.md derives the
// heuristics (Eq. 2.7-2.10).
#pragma once

namespace ps {

// How the weights of Eq. 2.6 are chosen: balance (Eq. 2.7), power with beta = 2 (Eq. 2.8),
// maximum (Eq. 2.9).
enum class Heuristic { Balance, Power, Maximum };

// One sampling technique as MIS sees it at one sample x: it takes n samples (n_i; in the
// one-sample model the probability c_i of choosing it) and would produce x with density pdf
// (p_i(x), per unit solid angle for directions; 0 if it cannot produce x, e.g. a delta light
// for BSDF sampling).
struct Technique {
    float n = 1.0f;
    float pdf = 0.0f;
};

// The weight w_i(x) of technique i among techniques[0 .. count-1] at a sample x that technique
// i produced (Eq. 2.7-2.9). Over the techniques that can produce x the weights sum to 1; 0 if
// n_i p_i = 0. Finite for pdfs from 1e-30 to 1e30 (Eq. 2.10): never square a raw pdf.
float misWeight(Heuristic heuristic, int i, const Technique* techniques, int count);

// The two-technique case every integrator of lessons 2 and 3 uses: the weight of the technique
// that took the sample (n samples, pdf pThis) against the other one (nOther, pOther).
inline float misWeight(Heuristic heuristic, float nThis, float pThis, float nOther, float pOther) {
    const Technique t[2] = {{nThis, pThis}, {nOther, pOther}};
    return misWeight(heuristic, 0, t, 2);
}

}  // namespace ps
