// Lesson 3 — the walks built on randomWalk (plumbing: read it, nothing to write here): the camera
// walk (from a camera ray, or resumed from a WalkStart), no roulette of its own, and the density
// with which a walk leaves a vertex. Interface: lessons/03-path-tracing/walk.h.
#include "03-path-tracing/walk.h"

namespace ps {

namespace {
// The camera walk's own BSDF sampling: radiance flows against the walk.
bool sampleRadianceBSDF(const Material& m, const Vec3& n, const Vec3& wo, const Vec2& u, float uLobe, BSDFSample& s) {
    return sampleBSDF(m, n, wo, u, uLobe, Transport::Radiance, s);
}
}  // namespace

void cameraWalk(const Scene& scene, const Ray& ray, Rng& rng, const WalkOptions& opt, const WalkVisitor& visit) {
    WalkStart start;
    start.ray = ray;
    randomWalk(scene, start, sampleRadianceBSDF, rng, opt, visit);
}

void cameraWalk(const Scene& scene, const WalkStart& start, Rng& rng, const WalkOptions& opt,
                const WalkVisitor& visit) {
    randomWalk(scene, start, sampleRadianceBSDF, rng, opt, visit);
}

float alwaysSurvive(const Color&, int) { return 1.0f; }

float pdfWalk(const Scene& scene, const WalkVertex& v, const Vec3& wi) {
    if (v.sampler) return v.sampler->pdf(scene, v, wi);
    return pdfBSDF(scene.materials[v.sp.material], v.sp.n, v.wo, wi);
}

}  // namespace ps
