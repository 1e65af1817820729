// Lesson 13 — merging at a camera vertex: lesson 8's density estimate over the light vertices of
// every light subpath of the iteration (Eq. 13.3), each merge weighted against every connection
// and every other merge of the path it stands for (Eq. 13.11). Interface: lessons/13-vcm/vcm.h.
// Equation numbers refer to lessons/13-vcm/README.md.
#include "13-vcm/vcm.h"
#include "todo.h"

namespace ps {

ReversePdfs mergePdfs(const Scene& scene, const PathVertex* y, int e, const PathVertex* z, int f) {
    //! TODO(13) The merge's four junction densities, per unit area, in the roles vcm.h and README 1.5 give
    //!          them. Pitfalls (README 6): the BSDF is the camera vertex's, the arriving direction the light's.
    //! STUB (void)scene; (void)y; (void)e; (void)z; (void)f;
    //! STUB return PS_TODO("lesson 13: mergePdfs", ReversePdfs());
    //! BEGIN
    ReversePdfs r;
    const PathVertex& zf = z[f];
    const Material& m = scene.materials[size_t(zf.sp.material)];
    const Vec3 wo = direction(zf, z[f - 1]), wLight = direction(y[e], y[e - 1]);
    r.lightEnd = pdfSolidAngleToArea(pdfBSDF(m, zf.sp.n, wo, wLight), y[e], y[e - 1]);
    r.lightPrev = e >= 2 ? y[e - 2].pdfRev : 0.0f;
    r.cameraEnd = y[e].pdfFwd;
    r.cameraPrev = pdfSolidAngleToArea(pdfBSDF(m, zf.sp.n, wLight, wo), zf, z[f - 1]);
    return r;
    //! END
}

Color mergeAtVertex(const Scene& scene, const Subpath& camera, const MergeSums& cameraSums, int f,
                    const LightVertices& lights, const MergeOptions& opt, MergeRecorder* recorder) {
    //! TODO(13) The sum of C*_VM w_VM (Eq. 13.3, 13.11) over the light vertices merged with z_f (vcm.h; w = 1 for
    //!          Ppm), each merge reported to the recorder if any. Pitfalls (README 6): the search takes r^2; the
    //!          merged path has e + f + 1 vertices and the same depth limit as a connection.
    //! STUB (void)scene; (void)camera; (void)cameraSums; (void)f; (void)lights; (void)opt; (void)recorder;
    //! STUB return PS_TODO("lesson 13: mergeAtVertex", Color(0.0f));
    //! BEGIN
    thread_local std::vector<LightVertexRef> found;
    const PathVertex& z = camera[size_t(f)];
    const double r = opt.radius;
    lightVerticesWithin(lights, z.p(), float(r * r), found);
    Color sum(0.0f);
    if (found.empty()) return sum;
    const Material& material = scene.materials[size_t(z.sp.material)];
    const Vec3 wo = direction(z, camera[size_t(f) - 1]);
    VcmMis mis;
    mis.heuristic = opt.heuristic;
    mis.eta = mergeFactor(r, opt.lightPaths);
    mis.connections = opt.mode == VcmMode::Vcm;
    const SubpathSide cameraSide{camera.data(), cameraSums.data(), f + 1};
    const float normalisation = static_cast<float>(1.0 / (double(kPi) * r * r * double(opt.lightPaths)));
    for (const LightVertexRef& ref : found) {
        const int e = int(ref.index);
        if (e + f - 1 > opt.maxDepth) continue;
        const PathVertex* light = lights.subpath(ref.path);
        const PathVertex& y = light[e];
        const Color fs = evalBSDF(material, z.sp.n, wo, direction(y, light[e - 1]));
        if (isBlack(fs)) continue;
        const Color unweighted = y.beta * fs * z.beta * normalisation;
        float w = 1.0f;
        if (opt.mode != VcmMode::Ppm) {
            const ReversePdfs rev = mergePdfs(scene, light, e, camera.data(), f);
            const float wBpt = misWeightRecursive(light, e, camera.data(), f + 1, rev, opt.heuristic);
            const double m = mergeTerms({light, lights.subpathSums(ref.path), e}, cameraSide, rev, opt.heuristic);
            w = misWeightMerge(wBpt, !light[e - 1].specular, rev, m, mis);
        }
        sum += unweighted * w;
        if (recorder) recorder->add(ref, f, unweighted, w);
    }
    return sum;
    //! END
}

}  // namespace ps
