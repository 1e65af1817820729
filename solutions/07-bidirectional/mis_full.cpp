// Lesson 7 — MIS weights from the full list of the joined path's technique pdfs (Eq. 7.5-7.7).
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

bool techniqueSamples(const SubpathVertex* x, int n, int sPrime) {
    //! TODO(07) Eq. 7.7: false if sPrime >= n (t' = 0: the pinhole cannot be hit); s' = 0:
    //!          !x[0].deltaPosition; otherwise x[s'-1] and x[s'] must both be non-delta, and
    //!          not (s' == 1 && n == 2 && x[0].infinite).
    //! STUB (void)x; (void)n; (void)sPrime;
    //! STUB return PS_TODO("lesson 07: techniqueSamples", false);
    //! BEGIN
    if (sPrime < 0 || sPrime >= n) return false;
    if (sPrime == 0) return !x[0].deltaPosition;
    if (x[sPrime - 1].delta || x[sPrime].delta) return false;
    return !(sPrime == 1 && n == 2 && x[0].infinite);
    //! END
}

float misWeightFull(const SubpathVertex* y, int s, const SubpathVertex* z, int t, const ReversePdfs& rev, Heuristic h) {
    //! TODO(07) Eq. 7.5-7.7. n = s + t; x[i] = y[i] for i < s, x[s + j] = z[t - 1 - j];
    //!          pL[i] (x_i sampled from the light side) and pE[i] (from the camera side):
    //!          light vertex y_i: pL = pdfFwd, pE = pdfRev, but rev.lightEnd for i = s-1 and
    //!          rev.lightPrev for i = s-2; camera vertex z_j: pE = pdfFwd, pL = pdfRev, but
    //!          rev.cameraEnd for j = t-1 and rev.cameraPrev for j = t-2. Take the numbers as they
    //!          are (a specular vertex's are its lobe's coefficients, Eq. 7.7a; a 0 is a 0). In double: for every s' with
    //!          techniqueSamples(x, n, s'), p = prod_{i<s'} pL[i] * prod_{i>=s'} pE[i],
    //!          q = p (balance) or p^2 (power); w = q_s / sum of q. 0 if the sum is 0.
    //! STUB (void)y; (void)s; (void)z; (void)t; (void)rev; (void)h;
    //! STUB return PS_TODO("lesson 07: misWeightFull", 0.0f);
    //! BEGIN
    const int n = s + t;
    std::vector<SubpathVertex> x(static_cast<size_t>(n));
    std::vector<double> pL(static_cast<size_t>(n)), pE(static_cast<size_t>(n));
    for (int i = 0; i < s; ++i) {
        x[size_t(i)] = y[i];
        pL[size_t(i)] = y[i].pdfFwd;
        pE[size_t(i)] = i == s - 1 ? rev.lightEnd : i == s - 2 ? rev.lightPrev : y[i].pdfRev;
    }
    for (int j = 0; j < t; ++j) {
        const size_t i = size_t(s + t - 1 - j);
        x[i] = z[j];
        pE[i] = z[j].pdfFwd;
        pL[i] = j == t - 1 ? rev.cameraEnd : j == t - 2 ? rev.cameraPrev : z[j].pdfRev;
    }
    const double beta = h == Heuristic::Power ? 2.0 : 1.0;
    double sum = 0.0, mine = 0.0;
    for (int sp = 0; sp <= n; ++sp) {
        if (!techniqueSamples(x.data(), n, sp)) continue;
        double p = 1.0;
        for (int i = 0; i < n; ++i) p *= i < sp ? pL[size_t(i)] : pE[size_t(i)];
        const double q = std::pow(p, beta);
        sum += q;
        if (sp == s) mine = q;
    }
    return sum > 0.0 ? static_cast<float>(mine / sum) : 0.0f;
    //! END
}

}  // namespace ps
