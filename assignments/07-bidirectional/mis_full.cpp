// Lesson 7 — MIS weights from the full list of the joined path's technique pdfs (Eq. 7.5-7.7).
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

bool techniqueSamples(const PathVertex* x, int n, int sPrime) {
    // TODO(07) Eq. 7.7 / 7.12: whether technique s' can make the joined path x_0 .. x_{n-1}.
    //          Pitfalls: t' = 0 never at the pinhole (it cannot be hit; a camera model's point,
    //          x[n-1].onCamera, can: then always), s' = 0 not with a point light, no edge at a specular
    //          vertex, and not the background joined straight to the pinhole.
    (void)x; (void)n; (void)sPrime;
    return PS_TODO("lesson 07: techniqueSamples", false);
}

float misWeightFull(const PathVertex* y, int s, const PathVertex* z, int t, const ReversePdfs& rev, Heuristic h) {
    // TODO(07) Eq. 7.5-7.7: w_{s,t} = p_s^b / sum_{s'} p_{s'}^b over the techniques that can make
    //          the joined path x = y_0 .. y_{s-1} z_{t-1} .. z_0, with p_{s'} the product of the
    //          light-side densities of x_0 .. x_{s'-1} and the camera-side ones of the rest
    //          (pdfFwd / pdfRev, replaced by rev's four numbers next to the connection).
    //          Pitfalls: in double; a 0 stays 0 (no "0 counted as 1"); 0 if the sum is 0.
    (void)y; (void)s; (void)z; (void)t; (void)rev; (void)h;
    return PS_TODO("lesson 07: misWeightFull", 0.0f);
}

}  // namespace ps
