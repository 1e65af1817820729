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
    // TODO(13) Eq. 13.9 for one side: the merges at the endpoint e, at e - 1 and before (D_e,
    //          sums[e]), with the connection's two new reverse densities in place of the stored
    //          ones (ratio gives r'^b); mu from mergeable, mergeEnd for the endpoint itself.
    //          e = 0: the endpoint alone. Pitfall: D_e is read as it is (it knows nothing of the
    //          connection); the ratios of e and e - 1 multiply what lies before them.
    (void)path; (void)sums; (void)e; (void)revEnd; (void)revPrev; (void)mergeEnd; (void)h;
    return PS_TODO("lesson 13: mergeTerms (one side)", 0.0);
}

}  // namespace

bool mergeable(const PathVertex* path, int i) {
    // TODO(13) Eq. 13.7: mu_i, where a merge may happen: not the subpath's first vertex, on a
    //          surface, not specular. Pitfall: a merge at a specular vertex would need f of a Dirac
    //          delta for a pair of directions no sampler chose.
    (void)path; (void)i;
    return PS_TODO("lesson 13: mergeable", false);
}

void updateMergeSum(const Subpath& path, size_t i, Heuristic h, MergeSums& sums) {
    // TODO(13) Eq. 13.8: sums[i] = D_i (D_0 = D_1 = 0), from vertex i - 2's stored pdfRev and
    //          pdfFwd and D_{i-1}. Pitfall: the merge term of vertex i - 2 is its REVERSE density
    //          to the power b (the other side would sample it), not the ratio.
    (void)path; (void)i; (void)h;
    sums.resize(i + 1);
    sums[i] = PS_TODO("lesson 13: updateMergeSum", 0.0);
}

double mergeTerms(const SubpathSide& light, const SubpathSide& camera, const ReversePdfs& rev, Heuristic h) {
    // TODO(13) Eq. 13.9: M = M^L + M^E, each side from its endpoint (sideTerms) with the
    //          connection's reverse densities (light side: lightEnd, lightPrev; camera side:
    //          cameraEnd, cameraPrev). Pitfalls: s = 0 has no light side, and its camera endpoint
    //          is the path's first vertex (on the light): no merge there; t = 1's endpoint is the
    //          camera.
    (void)light; (void)camera; (void)rev; (void)h;
    return PS_TODO("lesson 13: mergeTerms", 0.0);
}

float misWeightConnection(float wBpt, double mergeTermsM, const VcmMis& mis) {
    // TODO(13) Eq. 13.10: lesson 7's weight has the connections' sum in its denominator (1 / w);
    //          add the merges' eta^b M. In double. Pitfall: eta to the power b as well.
    (void)wBpt; (void)mergeTermsM; (void)mis;
    return PS_TODO("lesson 13: misWeightConnection", 0.0f);
}

float misWeightMerge(float wBpt, bool connects, const ReversePdfs& rev, double mergeTermsM, const VcmMis& mis) {
    // TODO(13) Eq. 13.11: the merge's own term (eta p_L(z_f))^b over the sum of every technique's,
    //          all relative to the connection (s, f + 1) of the same path: the connections' sum is
    //          1 / wBpt - 1 (lesson 7's weight counts its own technique as the 1) plus 1 if that
    //          connection is a technique; the merges' eta^b M. Without connections, only the
    //          merges. Pitfalls: p_L(z_f) is the LIGHT side's density of the camera vertex (rev);
    //          0 if the denominator is 0.
    (void)wBpt; (void)connects; (void)rev; (void)mergeTermsM; (void)mis;
    return PS_TODO("lesson 13: misWeightMerge", 0.0f);
}

}  // namespace ps
