// Lesson 10 — the walk with survival and splitting (Algorithm 10.1): lesson 3's random walk,
// which may go on from a vertex any number of times. Interface: lessons/10-adrrs/adrrs.h.
// Equation numbers refer to lessons/10-adrrs/README.md and lessons/03-path-tracing/README.md.
#include <algorithm>
#include "10-adrrs/adrrs.h"
#include "todo.h"

namespace ps {

void splittingWalk(const Scene& scene, const Ray& cameraRay, Rng& rng, int maxDepth, const ContinuationRule& rule,
                   const WalkVisitor& visit) {
    //! TODO(10) Algorithm 10.1: the tree of paths from cameraRay, depth first. A vertex is filled
    //!          and visited as in lesson 3's cameraWalk (the escape too; beta_0 = 1, specular at
    //!          bounces 0). From a vertex the walk may go on from (hit, visit returned true,
    //!          bounces < maxDepth): q = rule(v), cut to min(q, 1) once kMaxPathsPerCameraRay
    //!          paths have been started (1 + the extra continuations n - 1 of every split so far);
    //!          c = continuations(v.beta, q, rng); then c.n times: sample the BSDF with
    //!          sampleBSDF(material, n, wo, u, uLobe, Transport::Radiance, s), u = rng.uniform2()
    //!          drawn before uLobe = rng.uniform() (this continuation ends if it fails or
    //!          c.beta * s.weight is black) and follow the new path (scene.spawnRay) to its very
    //!          end before the next continuation samples.
    //!          Pitfall: recursion as deep as maxDepth may overflow the stack (the extreme tests
    //!          use maxDepth 100000): keep the open vertices in a std::vector.
    //! STUB (void)scene; (void)cameraRay; (void)rng; (void)maxDepth; (void)rule; (void)visit;
    //! STUB (void)PS_TODO("lesson 10: splittingWalk", 0);
    //! BEGIN
    // An open vertex: where `left` more continuations, each of throughput c.beta, still start.
    struct Open {
        WalkVertex v;
        Color beta;
        int left = 0;
    };
    std::vector<Open> open;
    int paths = 1;
    // Arrives along `ray`: intersect, visit, and if the walk may go on, decide how often.
    const auto arrive = [&](Ray ray, const Color& beta, int bounces, bool specular, float pdfPrev, const Vec3& pPrev) {
        Open o;
        WalkVertex& v = o.v;
        v.hit = scene.intersect(ray, v.sp);
        v.bounces = bounces;
        v.wo = -ray.d;
        v.beta = beta;
        v.specular = specular;
        v.pdfPrev = pdfPrev;
        v.pPrev = pPrev;
        if (!visit(v) || !v.hit || bounces == maxDepth) return;
        float q = rule(v);
        if (paths >= kMaxPathsPerCameraRay) q = std::min(q, 1.0f);
        const Continuations c = continuations(v.beta, q, rng);
        if (c.n <= 0) return;
        paths += c.n - 1;
        o.beta = c.beta;
        o.left = c.n;
        open.push_back(o);
    };
    arrive(cameraRay, Color(1.0f), 0, true, 0.0f, Vec3(0.0f));
    while (!open.empty()) {
        Open& top = open.back();
        if (top.left == 0) {
            open.pop_back();
            continue;
        }
        --top.left;
        const WalkVertex v = top.v;  // arrive() may grow `open`: copy before
        // Named, in this order: C++ evaluates a call's arguments in no fixed order.
        const Vec2 u = rng.uniform2();
        const float uLobe = rng.uniform();
        BSDFSample s;
        if (!sampleBSDF(scene.materials[v.sp.material], v.sp.n, v.wo, u, uLobe, Transport::Radiance, s)) continue;
        const Color beta = top.beta * s.weight;
        if (isBlack(beta)) continue;
        arrive(scene.spawnRay(v.sp, s.wi), beta, v.bounces + 1, s.delta, s.pdf, v.sp.p);
    }
    //! END
}

}  // namespace ps
