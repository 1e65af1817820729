// Lesson 8 — progressive photon mapping: the radius of each pass (Knaus and Zwicker's update) and
// one pass's estimate along a camera ray. Interface: lessons/08-photon-mapping/photonmap.h.
// Equation numbers refer to lessons/08-photon-mapping/README.md.
#include "08-photon-mapping/photonmap.h"
#include "todo.h"

namespace ps {

double ppmNextRadius2(double r2, int pass, double alpha) {
    //! TODO(08) r^2 of pass i + 1 from that of pass i >= 1 (Eq. 8.13). Pitfall: r^2 shrinks, not r.
    //! STUB (void)pass; (void)alpha;
    //! STUB return PS_TODO("lesson 08: ppmNextRadius2", r2);
    //! BEGIN
    return r2 * (double(pass) + alpha) / (double(pass) + 1.0);
    //! END
}

Color LiProgressive(const Scene& scene, const Ray& ray, Rng& rng, const PhotonMap& map, float r2, int maxDepth) {
    //! TODO(08) One pass's radiance along the camera ray (Eq. 8.14) on lesson 3's cameraWalk, as LiProgressive in
    //!          photonmap.h states it. Pitfalls (README 6): a fixed-radius box estimate, not k-nearest; emission only
    //!          where seen directly or through specular bounces (the estimate at x includes direct light).
    //! STUB (void)scene; (void)ray; (void)rng; (void)map; (void)r2; (void)maxDepth;
    //! STUB return PS_TODO("lesson 08: LiProgressive", Color(0.0f));
    //! BEGIN
    EstimateOptions opt;
    opt.filter = Filter::Box;
    opt.k = 0;
    opt.maxRadius = std::sqrt(r2);
    Color L(0.0f);
    cameraWalk(scene, ray, rng, {maxDepth, alwaysSurvive}, [&](const WalkVertex& v) {
        if (!v.hit) {
            if (v.specular) L += v.beta * scene.backgroundRadiance();
            return false;
        }
        if (v.specular && v.sp.light >= 0)
            L += v.beta * emittedRadiance(scene.lights[size_t(v.sp.light)], v.sp.n, v.wo);
        const Material& m = scene.materials[size_t(v.sp.material)];
        if (m.isDelta()) return true;
        if (v.bounces < maxDepth) L += v.beta * radianceEstimate(map, v.sp, m, v.wo, opt);
        return false;
    });
    return L;
    //! END
}

}  // namespace ps
