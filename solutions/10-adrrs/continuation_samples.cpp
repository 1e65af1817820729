// Lesson 10 — the pre-pass's samples of the radiance a path collects from each vertex on.
// Interface: lessons/10-adrrs/adrrs.h. Equation numbers refer to lessons/10-adrrs/README.md.
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

void continuationSamples(const std::vector<PrePassVertex>& path, std::vector<CacheSample>& out) {
    //! TODO(10) The pre-pass samples of one path (Eq. 10.8; adrrs.h). Pitfall: x_k's own light sample belongs to x_k.
    //! STUB (void)path; (void)out;
    //! STUB (void)PS_TODO("lesson 10: continuationSamples", 0);
    //! BEGIN
    // Suffix sums from the end: from[k] = sum_{j >= k} added_j.
    std::vector<Color> from(path.size(), Color(0.0f));
    Color sum(0.0f);
    for (size_t k = path.size(); k-- > 0;) {
        sum += path[k].added;
        from[k] = sum;
    }
    for (size_t k = 0; k < path.size(); ++k) {
        if (path[k].entry < 0) continue;
        const Color& b = path[k].beta;
        const Color& s = from[k];
        out.push_back({path[k].entry, Color(b.r > 0.0f ? s.r / b.r : 0.0f, b.g > 0.0f ? s.g / b.g : 0.0f,
                                            b.b > 0.0f ? s.b / b.b : 0.0f)});
    }
    //! END
}

}  // namespace ps
