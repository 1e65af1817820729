// Lesson 13 — multiple importance sampling over connections AND merges, in the recursive form:
// lesson 7's partial sums (misSum) and weights extended by the merging terms (Eq. 13.7-13.11).
// Interface: lessons/13-vcm/vcm.h. Equation numbers refer to lessons/13-vcm/README.md.
#include "13-vcm/vcm.h"
#include "todo.h"

namespace ps {

namespace {

double powerOf(double x, Heuristic h) { return h == Heuristic::Power ? x * x : x; }

// (pdfRev / pdfFwd)^b of a vertex with a reverse density pdfRev (Eq. 7.8's ratio): 0 where the
// vertex has no forward density.
[[maybe_unused]] double ratio(double pdfRev, const PathVertex& v, Heuristic h) {
    return v.pdfFwd > 0.0f ? powerOf(pdfRev / double(v.pdfFwd), h) : 0.0;
}

// The merging sum of one side of a joined path, from its endpoint e with the connection's two new
// reverse densities (Eq. 13.9); mergeEnd: whether the endpoint itself can be merged at.
[[maybe_unused]] double sideTerms(const PathVertex* path, const double* sums, int e, double revEnd, double revPrev,
                                  bool mergeEnd, Heuristic h) {
    // TODO(13) One side's term of Eq. 13.9 (M^L or M^E) from its endpoint e, with the connection's two reverse
    //          densities in place of the stored ones. Pitfall: D_e is read as stored; e = 0 has the endpoint alone.
    (void)path; (void)sums; (void)e; (void)revEnd; (void)revPrev; (void)mergeEnd; (void)h;
    return PS_TODO("lesson 13: mergeTerms (one side)", 0.0);
}

}  // namespace

bool mergeable(const PathVertex* path, int i) {
    // TODO(13) mu_i of Eq. 13.7 (vcm.h). Pitfall (README 6): no merge at a subpath's first vertex nor a specular one.
    (void)path; (void)i;
    return PS_TODO("lesson 13: mergeable", false);
}

void updateMergeSum(const Subpath& path, size_t i, Heuristic h, MergeSums& sums) {
    // TODO(13) D_i of Eq. 13.8 into sums[i] (vcm.h). Pitfall (README 6): vertex i - 2's merge term is its REVERSE
    //          density to the power b, not its ratio.
    (void)path; (void)i; (void)h;
    sums.resize(i + 1);
    sums[i] = PS_TODO("lesson 13: updateMergeSum", 0.0);
}

double mergeTerms(const SubpathSide& light, const SubpathSide& camera, const ReversePdfs& rev, Heuristic h) {
    // TODO(13) M of Eq. 13.9, without eta^b (vcm.h). Pitfalls (README 6): for s = 0 the camera endpoint is the
    //          path's first vertex (no merge there); for t = 1 it is the camera.
    (void)light; (void)camera; (void)rev; (void)h;
    return PS_TODO("lesson 13: mergeTerms", 0.0);
}

float misWeightConnection(float wBpt, double mergeTermsM, const VcmMis& mis) {
    // TODO(13) w^VCM of Eq. 13.10, computed in double. Pitfall (README 6): eta takes the exponent b as well.
    (void)wBpt; (void)mergeTermsM; (void)mis;
    return PS_TODO("lesson 13: misWeightConnection", 0.0f);
}

float misWeightMerge(float wBpt, bool connects, const ReversePdfs& rev, double mergeTermsM, const VcmMis& mis) {
    // TODO(13) w_M of Eq. 13.11 (vcm.h), 0 where its denominator is 0. Pitfall (README 6): the numerator's
    //          density is the light side's at the merge vertex; without connections, merges only.
    (void)wBpt; (void)connects; (void)rev; (void)mergeTermsM; (void)mis;
    return PS_TODO("lesson 13: misWeightMerge", 0.0f);
}

}  // namespace ps
