// Lesson 8 — photon tracing: lesson 5's light walk with a roulette that keeps the photons' power
// constant, photons stored at non-specular hits. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include <algorithm>
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

float photonSurvival(const Color& throughput, int bounces) {
    //! TODO(08) Eq. 8.3: q = min(1, largest component of the throughput), at every bounce (no
    //!          waiting for a few bounces as lesson 3 does, no floor: either would change the
    //!          power of the photons stored after it).
    //! STUB (void)throughput; (void)bounces;
    //! STUB return PS_TODO("lesson 08: photonSurvival", 1.0f);
    //! BEGIN
    (void)bounces;
    return std::min(1.0f, maxComponent(throughput));
    //! END
}

void tracePhoton(const Scene& scene, Rng& rng, int maxDepth, MapKind kind, int emitted, std::vector<Photon>& out,
                 const PhotonVisitor& visit, const ContinuationRule& continuation) {
    //! TODO(08) Eq. 8.1-8.3: lightWalk(scene, rng, options, visitor), the options {maxDepth,
    //!          photonSurvival} with `continuation` as their continuation rule. The visitor
    //!          goes on at y0 (bounces 0). At a surface (bounces >= 1) with material m:
    //!          - m.isDelta(): a specular bounce, nothing stored; go on.
    //!          - else a photon {p = sp.p, power = beta / emitted, setWLight(v.wo)} goes to out
    //!            for the global map always; for the caustic map only if every surface before this
    //!            one was specular and there was at least one (L S+ D). The caustic walk ends at
    //!            its first non-specular surface, the global walk goes on.
    //!          Last, at every vertex, the photon visitor if there is one (visit(v, the photon to
    //!          store or nullptr)): its false drops that photon and ends the walk.
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
