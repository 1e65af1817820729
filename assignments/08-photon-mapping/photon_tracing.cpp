// Lesson 8 — photon tracing: lesson 5's light walk with a roulette that keeps the photons' power
// constant, photons stored at non-specular hits. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

float photonSurvival(const Color& throughput, int bounces) {
    // TODO(08) Eq. 8.3: q = min(1, largest component of the throughput), at every bounce (no
    //          waiting for a few bounces as lesson 3 does, no floor: either would change the
    //          power of the photons stored after it).
    (void)throughput; (void)bounces;
    return PS_TODO("lesson 08: photonSurvival", 1.0f);
}

void tracePhoton(const Scene& scene, Rng& rng, int maxDepth, MapKind kind, int emitted, std::vector<Photon>& out,
                 const PhotonVisitor& visit, const ContinuationRule& continuation) {
    // TODO(08) Eq. 8.1-8.3: lightWalk(scene, rng, options, visitor), the options {maxDepth,
    //          photonSurvival} with `continuation` as their continuation rule. The visitor
    //          goes on at y0 (bounces 0). At a surface (bounces >= 1) with material m:
    //          - m.isDelta(): a specular bounce, nothing stored; go on.
    //          - else a photon {p = sp.p, power = beta / emitted, setWLight(v.wo)} goes to out
    //            for the global map always; for the caustic map only if every surface before this
    //            one was specular and there was at least one (L S+ D). The caustic walk ends at
    //            its first non-specular surface, the global walk goes on.
    //          Last, at every vertex, the photon visitor if there is one (visit(v, the photon to
    //          store or nullptr)): its false drops that photon and ends the walk.
    (void)scene; (void)rng; (void)maxDepth; (void)kind; (void)emitted; (void)out; (void)visit;
    (void)continuation;
    (void)PS_TODO("lesson 08: tracePhoton", 0);
}

}  // namespace ps
