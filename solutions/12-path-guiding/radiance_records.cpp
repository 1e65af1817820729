// Lesson 12 — what a camera path teaches the field: one record per sampled direction of the
// radiance that arrived along it. Interface: lessons/12-path-guiding/guiding.h. Equation numbers
// refer to lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

void radianceRecords(const std::vector<GuideVertex>& path, std::vector<RadianceRecord>& out) {
    //! TODO(12) Eq. 12.12, 12.13: for every vertex k with a cell (cell >= 0), in order: the
    //!          radiance that arrived along its wi is what the vertices after it added, with the
    //!          next vertex's MIS-weighted emission replaced by its full emission (emittedFull),
    //!          divided channel by channel by the vertex's throughput (0 in a channel where that
    //!          is 0); the record's value is the mean of its channels divided by the vertex's pdf.
    //!          Pitfalls: x_k's own `added` is its light sample, along another direction than
    //!          wi; the throughput is beta_k times the sample's weight, not beta_k alone.
    //! STUB (void)path; (void)out;
    //! STUB (void)PS_TODO("lesson 12: radianceRecords", 0);
    //! BEGIN
    // after[k] = the sum of added_j over j > k.
    std::vector<Color> after(path.size(), Color(0.0f));
    Color sum(0.0f);
    for (size_t k = path.size(); k-- > 0;) {
        after[k] = sum;
        sum += path[k].added;
    }
    for (size_t k = 0; k < path.size(); ++k) {
        const GuideVertex& v = path[k];
        if (v.cell < 0) continue;
        Color L = after[k];
        if (k + 1 < path.size()) L += path[k + 1].emittedFull - path[k + 1].emitted;
        const Color& t = v.throughput;
        const Color Li(t.r > 0.0f ? L.r / t.r : 0.0f, t.g > 0.0f ? L.g / t.g : 0.0f, t.b > 0.0f ? L.b / t.b : 0.0f);
        out.push_back({v.cell, v.wi, (Li.r + Li.g + Li.b) / 3.0f / v.pdf});
    }
    //! END
}

}  // namespace ps
