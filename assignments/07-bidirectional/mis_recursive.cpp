// Lesson 7 — MIS weights with O(1) work per vertex (Eq. 7.8-7.10): partial sums carried along
// each subpath, completed at the connection with the four reverse pdfs it creates.
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

namespace {

double heuristicPower(double r, Heuristic h) { return h == Heuristic::Power ? r * r : r; }

// c_j of Eq. 7.10 for vertex j of a subpath (camera subpaths start with the camera).
[[maybe_unused]] double connectible(const PathVertex* path, int j) {
    // TODO(07) c_j of Eq. 7.10 for path[j] (updateMisSum in bpt.h). Pitfall: a subpath's first vertex (pinhole, camera
    //          model's point, point light) and the background.
    (void)path; (void)j;
    return PS_TODO("lesson 07: connectible", 0.0);
}

// r_j^b with the given reverse pdf (Eq. 7.8); 0 where the vertex has no forward density (only
// ever multiplied by c_j = 0 there).
[[maybe_unused]] double ratio(float pdfRev, const PathVertex& v, Heuristic h) {
    return v.pdfFwd > 0.0f ? heuristicPower(double(pdfRev) / double(v.pdfFwd), h) : 0.0;
}

// The sum over the techniques that move the connection into this subpath (Eq. 7.9), for the
// endpoint e = path[e] with the connection's reverse pdfs of path[e] and path[e-1].
[[maybe_unused]] double subpathSum(const PathVertex* path, int e, float revEnd, float revPrev, Heuristic h) {
    // TODO(07) The endpoint's partial sum with the connection's two new reverse densities (Eq. 7.9).
    (void)path; (void)e; (void)revEnd; (void)revPrev; (void)h;
    return PS_TODO("lesson 07: subpathSum", 0.0);
}

}  // namespace

void updateMisSum(Subpath& path, size_t i, Heuristic h) {
    // TODO(07) B_i of Eq. 7.9 into path[i].misSum (bpt.h). Pitfall: only once path[i-2].pdfRev is known.
    (void)path; (void)i; (void)h;
    (void)PS_TODO("lesson 07: updateMisSum", 0);
}

float misWeightRecursive(const PathVertex* y, int s, const PathVertex* z, int t, const ReversePdfs& rev, Heuristic h) {
    // TODO(07) w_{s,t} by Eq. 7.8 from the endpoints' sums. Pitfall: s = 0 has no light sum, t = 0 no camera sum.
    (void)y; (void)s; (void)z; (void)t; (void)rev; (void)h;
    return PS_TODO("lesson 07: misWeightRecursive", 0.0f);
}

}  // namespace ps
