// Lesson 9 — the target of multiplexed MLT: one BPT technique's MIS-weighted contribution over
// the probability of choosing it. Interface: lessons/09-metropolis/mmlt.h. Equation numbers refer
// to lessons/09-metropolis/README.md (lesson 7's to lessons/07-bidirectional/README.md).
#include <algorithm>
#include <cmath>
#include "09-metropolis/mmlt.h"
#include "todo.h"

namespace ps {

float techniqueProbability(int k) {
    // TODO(09) Eq. 9.12: p_k(s), uniform over the k + 1 techniques s = 0 .. k of path length k.
    (void)k;
    return PS_TODO("lesson 09: techniqueProbability", 0.0f);
}

int selectTechnique(int k, float u) {
    // TODO(09) Eq. 9.12: s = floor(u (k + 1)), at most k (u close to 1 may round up).
    (void)k; (void)u;
    return PS_TODO("lesson 09: selectTechnique", 0);
}

PathSample multiplexedTarget(const Scene& scene, const SubpathPair& paths, int k, int s) {
    // TODO(09) Eq. 9.12: t = k + 1 - s; c = connectTechnique(scene, paths, s, t). Valid: its MIS
    //          weight w = misWeightRecursive(y, s, paths.camera.data(), t, c.rev, Heuristic::Power)
    //          with y = &c.sampledLight for s = 1, else paths.light.data() (as lesson 7's
    //          bptSample); L = c.value w / techniqueProbability(k); t = 1: also divided by
    //          width * height (scene.camera) and raster = c.raster; t >= 2: raster = paths.raster.
    //          I = max(0, luminance(L)). Not valid: L = 0, I = 0, raster = paths.raster.
    //          Pitfalls: without the weight every technique counts the whole path (the image is
    //          about k + 1 times too bright); without 1 / p_k(s) the bootstrap's b_k is k + 1 times
    //          too small (the chain still visits the right states: only the brightness is off).
    (void)scene; (void)paths; (void)k; (void)s;
    return PS_TODO("lesson 09: multiplexedTarget", PathSample{});
}

}  // namespace ps
