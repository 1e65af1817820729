// Lesson 12 — what a camera sample teaches the field: one record per sampled direction of the
// radiance that arrived along it. Interface: lessons/12-path-guiding/guiding.h. Equation numbers
// refer to lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

void radianceRecords(const std::vector<GuideVertex>& path, std::vector<RadianceRecord>& out) {
    //! TODO(12) The records of one camera sample, in vertex order (Eq. 12.12, 12.13; guiding.h). Pitfalls
    //!          (README 6): divide by the throughput and by the pdf; x_j's emission counts in full, x_from's light
    //!          sample does not (another direction); a branch ends where a vertex comes from an earlier one (a split).
    //! STUB (void)path; (void)out;
    //! STUB (void)PS_TODO("lesson 12: radianceRecords", 0);
    //! BEGIN
    // branch[j]: the sum of `added` over x_j's branch. A vertex comes after the one it was sampled
    // from, so one pass from the end adds every branch into the vertex it grew from.
    std::vector<Color> branch(path.size(), Color(0.0f));
    for (size_t j = path.size(); j-- > 0;) {
        branch[j] += path[j].added;
        if (path[j].from >= 0) branch[size_t(path[j].from)] += branch[j];
    }
    for (size_t j = 0; j < path.size(); ++j) {
        const GuideVertex& v = path[j];
        if (v.cell < 0) continue;
        const Color L = branch[j] - v.emitted + v.emittedFull;
        const Color& t = v.throughput;
        const Color Li(t.r > 0.0f ? L.r / t.r : 0.0f, t.g > 0.0f ? L.g / t.g : 0.0f, t.b > 0.0f ? L.b / t.b : 0.0f);
        out.push_back({v.cell, v.side, v.wi, (Li.r + Li.g + Li.b) / 3.0f / v.pdf});
    }
    //! END
}

}  // namespace ps
