// Lesson 8 — photon tracing: lesson 5's light walk with a roulette that keeps the photons' power
// constant, photons stored at non-specular hits. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

float photonSurvival(const Color& throughput, int bounces) {
    //! TODO(08) The survival probability q of Eq. 8.3 (photonmap.h). Pitfall (README 6): lesson 3's rule (a delay, a
    //!          floor) changes the power of every photon stored after it.
    //! STUB (void)throughput; (void)bounces;
    //! STUB return PS_TODO("lesson 08: photonSurvival", 1.0f);
    //! BEGIN
    (void)bounces;
    return std::min(1.0f, maxComponent(throughput));
    //! END
}

void tracePhoton(const Scene& scene, Rng& rng, int maxDepth, MapKind kind, int emitted, std::vector<Photon>& out,
                 const PhotonVisitor& visit, const ContinuationRule& continuation) {
    //! TODO(08) One photon path (Eq. 8.1-8.3) on lesson 5's lightWalk with photonSurvival and `continuation`, appending
    //!          to out the photons tracePhoton in photonmap.h describes; the photon visitor, if any, comes last at
    //!          every vertex. Pitfalls (README 6): no photon at y_0 or on mirrors and glass; power beta / emitted; the
    //!          caustic map is L S+ D.
    //! STUB (void)scene; (void)rng; (void)maxDepth; (void)kind; (void)emitted; (void)out; (void)visit;
    //! STUB (void)continuation;
    //! STUB (void)PS_TODO("lesson 08: tracePhoton", 0);
    //! BEGIN
    bool onlySpecular = true;  // every surface so far was specular
    const float invN = 1.0f / float(emitted);
    WalkOptions opt(maxDepth, photonSurvival);
    opt.continuation = continuation;
    lightWalk(scene, rng, opt, [&](const WalkVertex& v, const LightPathStart&) {
        if (v.bounces == 0) return !visit || visit(v, nullptr);
        const Material& m = scene.materials[size_t(v.sp.material)];
        if (m.isDelta()) return !visit || visit(v, nullptr);
        bool goOn = kind == MapKind::Global;
        if (kind == MapKind::Global || (onlySpecular && v.bounces >= 2)) {
            Photon ph;
            ph.p = v.sp.p;
            ph.power = v.beta * invN;
            ph.setWLight(v.wo);
            if (!visit || visit(v, &ph)) out.push_back(ph);
            else goOn = false;
        } else if (visit && !visit(v, nullptr)) {
            goOn = false;
        }
        onlySpecular = false;
        return goOn;
    });
    //! END
}

}  // namespace ps
