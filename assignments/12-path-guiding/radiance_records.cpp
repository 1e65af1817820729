// Lesson 12 — what a camera sample teaches the field: one record per sampled direction of the
// radiance that arrived along it. Interface: lessons/12-path-guiding/guiding.h. Equation numbers
// refer to lessons/12-path-guiding/README.md.
#include "12-path-guiding/guiding.h"
#include "todo.h"

namespace ps {

void radianceRecords(const std::vector<GuideVertex>& path, std::vector<RadianceRecord>& out) {
    // TODO(12) The records of one camera sample, in vertex order (Eq. 12.12, 12.13; guiding.h). Pitfalls
    //          (README 6): divide by the throughput and by the pdf; x_j's emission counts in full, x_from's light
    //          sample does not (another direction); a branch ends where a vertex comes from an earlier one (a split).
    (void)path; (void)out;
    (void)PS_TODO("lesson 12: radianceRecords", 0);
}

}  // namespace ps
