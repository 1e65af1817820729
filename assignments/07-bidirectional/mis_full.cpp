// Lesson 7 — MIS weights from the full list of the joined path's technique pdfs (Eq. 7.5-7.7).
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

bool techniqueSamples(const SubpathVertex* x, int n, int sPrime) {
    // TODO(07) Eq. 7.7: false if sPrime >= n (t' = 0: the pinhole cannot be hit); s' = 0:
    //          !x[0].deltaPosition; otherwise x[s'-1] and x[s'] must both be non-delta, and
    //          not (s' == 1 && n == 2 && x[0].infinite).
    (void)x; (void)n; (void)sPrime;
    return PS_TODO("lesson 07: techniqueSamples", false);
}

float misWeightFull(const SubpathVertex* y, int s, const SubpathVertex* z, int t, const ReversePdfs& rev, Heuristic h) {
    // TODO(07) Eq. 7.5-7.7. n = s + t; x[i] = y[i] for i < s, x[s + j] = z[t - 1 - j];
    //          pL[i] (x_i sampled from the light side) and pE[i] (from the camera side):
    //          light vertex y_i: pL = pdfFwd, pE = pdfRev, but rev.lightEnd for i = s-1 and
    //          rev.lightPrev for i = s-2; camera vertex z_j: pE = pdfFwd, pL = pdfRev, but
    //          rev.cameraEnd for j = t-1 and rev.cameraPrev for j = t-2. Take the numbers as they
    //          are (a specular vertex's are its lobe's coefficients, Eq. 7.7a; a 0 is a 0). In double: for every s' with
    //          techniqueSamples(x, n, s'), p = prod_{i<s'} pL[i] * prod_{i>=s'} pE[i],
    //          q = p (balance) or p^2 (power); w = q_s / sum of q. 0 if the sum is 0.
    (void)y; (void)s; (void)z; (void)t; (void)rev; (void)h;
    return PS_TODO("lesson 07: misWeightFull", 0.0f);
}

}  // namespace ps
