// Lesson 7 — MIS weights with O(1) work per vertex (Eq. 7.8-7.10): partial sums carried along
// each subpath, completed at the connection with the four reverse pdfs it creates.
// Interface: lessons/07-bidirectional/bpt.h. Equation numbers refer to lessons/07-bidirectional/README.md.
#include "07-bidirectional/bpt.h"
#include "todo.h"

namespace ps {

namespace {

double heuristicPower(double r, Heuristic h) { return h == Heuristic::Power ? r * r : r; }

// c_j of Eq. 7.10 for vertex j of a subpath (camera subpaths start with the camera).
[[maybe_unused]] double connectible(const SubpathVertex* path, int j) {
    // TODO(07) Eq. 7.10: light subpath (path[0] is not the camera): c_0 = !path[0].deltaPosition;
    //          camera subpath: c_0 = 0, and c_1 = 0 if path[1] is at infinity; otherwise
    //          c_j = 1 if neither path[j] nor path[j-1] is delta, else 0.
    (void)path; (void)j;
    return PS_TODO("lesson 07: connectible", 0.0);
}

// r_j^b with the given reverse pdf (Eq. 7.8); 0 where the vertex has no forward density (only
// ever multiplied by c_j = 0 there).
[[maybe_unused]] double ratio(float pdfRev, const SubpathVertex& v, Heuristic h) {
    return v.pdfFwd > 0.0f ? heuristicPower(double(pdfRev) / double(v.pdfFwd), h) : 0.0;
}

// The sum over the techniques that move the connection into this subpath (Eq. 7.9), for the
// endpoint e = path[e] with the connection's reverse pdfs of path[e] and path[e-1].
[[maybe_unused]] double subpathSum(const SubpathVertex* path, int e, float revEnd, float revPrev, Heuristic h) {
    // TODO(07) Eq. 7.9: e == 0: r'_0 c_0; else r'_e (c_e + r'_{e-1} (c_{e-1} + path[e].misSum)),
    //          where r'_e = ratio(revEnd, path[e], h), r'_{e-1} = ratio(revPrev, path[e-1], h),
    //          c_j = connectible(path, j).
    (void)path; (void)e; (void)revEnd; (void)revPrev; (void)h;
    return PS_TODO("lesson 07: subpathSum", 0.0);
}

}  // namespace

void updateMisSum(Subpath& path, size_t i, Heuristic h) {
    // TODO(07) Eq. 7.9: path[i].misSum = 0 for i < 2; else
    //          r_{i-2}^b (c_{i-2} + path[i-1].misSum) with r_{i-2} = ratio(path[i-2].pdfRev, path[i-2], h)
    //          and c_{i-2} = connectible(path.data(), i - 2).
    (void)path; (void)i; (void)h;
    (void)PS_TODO("lesson 07: updateMisSum", 0);
}

float misWeightRecursive(const SubpathVertex* y, int s, const SubpathVertex* z, int t, const ReversePdfs& rev, Heuristic h) {
    // TODO(07) Eq. 7.8: w = 1 / (1 + light sum + camera sum), the light sum
    //          subpathSum(y, s - 1, rev.lightEnd, rev.lightPrev, h) if s >= 1 (else 0), the
    //          camera sum subpathSum(z, t - 1, rev.cameraEnd, rev.cameraPrev, h).
    (void)y; (void)s; (void)z; (void)t; (void)rev; (void)h;
    return PS_TODO("lesson 07: misWeightRecursive", 0.0f);
}

}  // namespace ps
