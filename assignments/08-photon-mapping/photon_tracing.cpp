// Lesson 8 — photon tracing: lesson 5's light walk with a roulette that keeps the photons' power
// constant, photons stored at non-specular hits. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

float photonSurvival(const Color& throughput, int bounces) {
    // TODO(08) The survival probability q of Eq. 8.3 (photonmap.h). Pitfall (README 6): lesson 3's rule (a delay, a
    //          floor) changes the power of every photon stored after it.
    (void)throughput; (void)bounces;
    return PS_TODO("lesson 08: photonSurvival", 1.0f);
}

void tracePhoton(const Scene& scene, Rng& rng, int maxDepth, MapKind kind, int emitted, std::vector<Photon>& out,
                 const PhotonVisitor& visit, const ContinuationRule& continuation) {
    // TODO(08) One photon path (Eq. 8.1-8.3) on lesson 5's lightWalk with photonSurvival and `continuation`, appending
    //          to out the photons tracePhoton in photonmap.h describes; the photon visitor, if any, comes last at
    //          every vertex. Pitfalls (README 6): no photon at y_0 or on mirrors and glass; power beta / emitted; the
    //          caustic map is L S+ D.
    (void)scene; (void)rng; (void)maxDepth; (void)kind; (void)emitted; (void)out; (void)visit;
    (void)continuation;
    (void)PS_TODO("lesson 08: tracePhoton", 0);
}

}  // namespace ps
