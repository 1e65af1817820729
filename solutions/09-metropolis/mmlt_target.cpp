// Lesson 9 — the target of multiplexed MLT: one BPT technique's MIS-weighted contribution over
// the probability of choosing it. Interface: lessons/09-metropolis/mmlt.h. Equation numbers refer
// to lessons/09-metropolis/README.md (lesson 7's to lessons/07-bidirectional/README.md).
#include <algorithm>
#include <cmath>
#include "09-metropolis/mmlt.h"
#include "todo.h"

namespace ps {

float techniqueProbability(int k) {
    //! TODO(09) p_k(s) of Eq. 9.12 (mmlt.h).
    //! STUB (void)k;
    //! STUB return PS_TODO("lesson 09: techniqueProbability", 0.0f);
    //! BEGIN
    return 1.0f / float(k + 1);
    //! END
}

int selectTechnique(int k, float u) {
    //! TODO(09) The technique s of probability p_k(s) (Eq. 9.12) for one number u. Pitfall: u close to 1 may round to k
    //!          + 1.
    //! STUB (void)k; (void)u;
    //! STUB return PS_TODO("lesson 09: selectTechnique", 0);
    //! BEGIN
    return std::min(int(u * float(k + 1)), k);
    //! END
}

PathSample multiplexedTarget(const Scene& scene, const SubpathPair& paths, int k, int s) {
    //! TODO(09) The chain's target at technique s (Eq. 9.12), as multiplexedTarget in mmlt.h states it; the MIS weight
    //!          as in lesson 7's bptSample. Pitfalls (README 6): without the weight the image is about k + 1 times too
    //!          bright; without 1 / p_k(s) the bootstrap's b_k is k + 1 times too small; t = 1 lands at the
    //!          connection's raster.
    //! STUB (void)scene; (void)paths; (void)k; (void)s;
    //! STUB return PS_TODO("lesson 09: multiplexedTarget", PathSample{});
    //! BEGIN
    PathSample out;
    out.raster = paths.raster;
    const int t = k + 1 - s;
    const Connection c = connectTechnique(scene, paths, s, t);
    if (!c.valid) return out;
    const PathVertex* y = s == 1 ? &c.sampledLight : paths.light.data();
    const float w = misWeightRecursive(y, s, paths.camera.data(), t, c.rev, Heuristic::Power);
    out.L = c.value * (w / techniqueProbability(k));
    if (t == 1) {
        out.L /= float(scene.camera.width()) * float(scene.camera.height());
        out.raster = c.raster;
    }
    out.I = std::max(0.0f, luminance(out.L));
    return out;
    //! END
}

}  // namespace ps
