// Lesson 7 — MIS weights from the full list of the joined path's technique pdfs (Eq. 7.5-7.7).
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

bool techniqueSamples(const PathVertex* x, int n, int sPrime) {
    // Given: a technique of this path at all (s' from 0 to n). Not the student's: a missing check
    // would read before the path (x[-1]), which no test can observe reliably.
    if (sPrime < 0 || sPrime > n) return false;
    //! TODO(07) Whether technique s' can make the joined path (Eq. 7.7, 7.12; techniqueSamples in bpt.h). Pitfall
    //!          (README 6): the pinhole and a point light cannot be hit, a camera model's point can.
    //! STUB (void)x; (void)n; (void)sPrime;
    //! STUB return PS_TODO("lesson 07: techniqueSamples", false);
    //! BEGIN
    if (sPrime == n) return x[n - 1].onCamera;
    if (sPrime == 0) return !x[0].pointLight;
    if (x[sPrime - 1].specular || x[sPrime].specular) return false;
    return !(sPrime == 1 && n == 2 && x[0].infinite);
    //! END
}

float misWeightFull(const PathVertex* y, int s, const PathVertex* z, int t, const ReversePdfs& rev, Heuristic h) {
    //! TODO(07) w_{s,t} from the full list of the joined path's densities (Eq. 7.5-7.7; misWeightFull in bpt.h).
    //!          Pitfalls (README 6): a specular vertex's density is its coefficient, and a 0 stays 0; sum in double; 0
    //!          if the sum is 0.
    //! STUB (void)y; (void)s; (void)z; (void)t; (void)rev; (void)h;
    //! STUB return PS_TODO("lesson 07: misWeightFull", 0.0f);
    //! BEGIN
    const int n = s + t;
    std::vector<PathVertex> x(static_cast<size_t>(n));
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
