// Lesson 3 — the random walk from the camera, shared by the three estimators (random_walk.cpp,
// next_event.cpp, path_mis.cpp) and by lesson 7's camera subpath. Interface:
// lessons/03-path-tracing/pathtracer.h. Equation numbers refer to lessons/03-path-tracing/README.md.
#include "03-path-tracing/pathtracer.h"
#include "todo.h"

namespace ps {

void cameraWalk(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth, const WalkVisitor& visit) {
    //! TODO(03) The walk x_0, x_1, ... of Eq. 3.4 from cameraRay, beta_0 = 1. At each vertex:
    //!          intersect, fill a WalkVertex (its fields say what each one holds: the escape is a
    //!          vertex too) and call visit; the walk ends if it returns false, on a miss, or at
    //!          bounces == maxDepth (Eq. 3.3: the vertex with maxDepth bounces is visited, no
    //!          bounce after it). Else sample the BSDF with sampleBSDF(material, n, wo, u,
    //!          uLobe, Transport::Radiance, s) (its weight is already f |cos| / pdf), end if it
    //!          fails or beta turns black, and play Russian roulette (Eq. 3.5) with
    //!          survivalProbability(beta, bounces + 1): a survivor is divided by q. Next ray:
    //!          scene.spawnRay.
    //!          Pitfall: the tests replay the walk's random numbers: draw u = rng.uniform2()
    //!          before uLobe = rng.uniform(), into variables (C++ evaluates a call's arguments
    //!          in no fixed order), the roulette's only when q < 1, and no others (the visitor
    //!          draws its own in between).
    //! STUB (void)scene; (void)cameraRay; (void)rng; (void)maxDepth; (void)visit;
    //! STUB (void)PS_TODO("lesson 03: cameraWalk", 0);
    //! BEGIN
    Color beta(1.0f);
    bool specular = true;
    float pdfPrev = 0.0f;
    Vec3 pPrev(0.0f);
    Ray ray = cameraRay;
    for (int bounces = 0;; ++bounces) {
        WalkVertex v;
        v.hit = scene.intersect(ray, v.sp);
        v.bounces = bounces;
        v.wo = -ray.d;
        v.beta = beta;
        v.specular = specular;
        v.pdfPrev = pdfPrev;
        v.pPrev = pPrev;
        if (!visit(v) || !v.hit) break;
        if (bounces == maxDepth) break;
        // Named, in this order: C++ evaluates a call's arguments in no fixed order.
        const Vec2 u = rng.uniform2();
        const float uLobe = rng.uniform();
        BSDFSample s;
        if (!sampleBSDF(scene.materials[v.sp.material], v.sp.n, v.wo, u, uLobe, Transport::Radiance, s)) break;
        specular = s.delta;
        pdfPrev = s.pdf;
        pPrev = v.sp.p;
        beta *= s.weight;
        if (isBlack(beta)) break;
        const float q = survivalProbability(beta, bounces + 1);
        if (q < 1.0f) {
            if (rng.uniform() >= q) break;
            beta /= q;
        }
        ray = scene.spawnRay(v.sp, s.wi);
    }
    //! END
}

}  // namespace ps
